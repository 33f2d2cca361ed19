// The sound system driven as the engine drives it (client messages -> ClientSoundFeed ->
// SoundSystem::update) into an in-memory sink, checked against Quake's facts computed here:
// when a sound starts, its waveform, its stereo volumes from Quake's spatialization formula,
// channel replacement, looping static sounds, the water ambient of a BSP leaf, pause, mute.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "common/file_io.h"
#include "formats/bsp.h"
#include "sound/client_sound_feed.h"
#include "sound/sound_system.h"
#include "support/allocation_counter.h"
#include "support/synth_wav.h"
#include "support/test_data.h"

namespace nq {
namespace {

constexpr double kFrameTime = 0.01;  // 441 output frames per engine frame at 44.1 kHz
constexpr size_t kFramesPerFrame = 441;
constexpr float kVolume = 0.7f;  // the `volume` cvar's default

std::vector<int16_t> pattern(size_t n) {
    std::vector<int16_t> s(n);
    for (size_t i = 0; i < n; ++i) s[i] = int16_t((int(i) * 2741) % 24001 - 12000);
    return s;
}

// What precaching makes of an 11025 Hz sound at 44100 Hz: linear interpolation, computed here.
std::vector<double> upsampled_x4(const std::vector<int16_t>& in) {
    std::vector<double> out(in.size() * 4);
    for (size_t i = 0; i < out.size(); ++i) {
        const size_t j = i / 4;
        const double f = double(i % 4) / 4.0;
        const double next = j + 1 < in.size() ? in[j + 1] : in[j];
        out[i] = std::round(in[j] * (1 - f) + next * f);
    }
    return out;
}

// Quake's SND_Spatialize for one side, in double precision, before truncation.
struct Expected {
    double left, right;
};
Expected quake_volumes(const std::array<double, 3>& source, const std::array<double, 3>& eye,
                       const std::array<double, 3>& right, double master, double attenuation) {
    std::array<double, 3> d{source[0] - eye[0], source[1] - eye[1], source[2] - eye[2]};
    const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    const double dot = (right[0] * d[0] + right[1] * d[1] + right[2] * d[2]) / len;
    const double dist = len * attenuation / 1000.0;
    return {std::max(0.0, master * (1 - dist) * (1 - dot)),
            std::max(0.0, master * (1 - dist) * (1 + dot))};
}

struct Rig {
    std::map<std::string, std::vector<uint8_t>> files;
    std::vector<std::string> printed;
    std::unique_ptr<SoundSystem> sound;
    ClientState client;
    ClientSoundFeed feed;
    Listener listener;
    SoundSettings settings;

    Rig() {
        sound = std::make_unique<SoundSystem>(
            std::make_unique<MemorySink>(kOutputRate, 1 << 20),
            [this](const std::string& path) -> Result<std::vector<uint8_t>> {
                if (auto it = files.find(path); it != files.end()) return it->second;
                if (auto real = read_file(test::lq1_dir() + "/" + path)) return real;
                return Error{path, 0, "not found"};
            },
            [this](std::string_view t) { printed.emplace_back(t); });
    }
    // A level whose sound precache list is `names` (index 1 onwards), viewed by entity 1.
    void new_level(const std::vector<std::string>& names) {
        svc::ServerInfo info;
        info.protocol = 15;
        info.max_clients = 1;
        info.models = {"maps/test.bsp"};
        info.sounds = names;
        ASSERT_FALSE(client.apply(info));
        ASSERT_FALSE(client.apply(svc::SetView{1}));
    }
    void frame(double dt = kFrameTime, bool paused = false) {
        listener.view_entity = client.view_entity();
        feed.feed(client, *sound, listener);
        sound->update(dt, paused, settings);
    }
    const std::vector<StereoFrame>& out() const {
        return static_cast<const MemorySink&>(sound->sink()).frames();
    }
};

svc::Sound sound_message(int entity, int channel, int index, const Vec3& origin, int volume,
                         float attenuation) {
    svc::Sound m;
    m.field_mask = protocol::SND_VOLUME | protocol::SND_ATTENUATION;
    m.entity = entity;
    m.channel = channel;
    m.sound = index;
    m.origin = origin;
    m.volume = volume;
    m.attenuation = attenuation;
    return m;
}

// Plays a svc_sound arriving in frame 5 from `source`, and checks the output.
void check_sound_from(const std::array<double, 3>& offset_right_forward, const char* what) {
    SCOPED_TRACE(what);
    Rig rig;
    const std::vector<int16_t> samples = pattern(1500);
    test::SynthWav wav;
    wav.samples = samples;
    rig.files["sound/test/beep.wav"] = test::write_wav(wav);
    rig.new_level({"test/beep.wav"});
    // The listener at (100, 50, 20) looking along yaw 30 degrees: Quake's right vector for
    // pitch 0, roll 0 is (sin yaw, -cos yaw, 0).
    const double yaw = 30.0 * M_PI / 180.0;
    const std::array<double, 3> eye{100, 50, 20};
    const std::array<double, 3> right{std::sin(yaw), -std::cos(yaw), 0};
    const std::array<double, 3> forward{std::cos(yaw), std::sin(yaw), 0};
    rig.listener = listener_for_view({100, 50, 20}, {0, 30, 0}, 1);
    std::array<double, 3> source{};
    for (int k = 0; k < 3; ++k) {
        source[k] =
            eye[k] + right[k] * offset_right_forward[0] + forward[k] * offset_right_forward[1];
    }
    const Vec3 origin{float(source[0]), float(source[1]), float(source[2])};
    // The wire's coordinates are what the client gets; use the float origin in the formula too.
    const std::array<double, 3> source_f{origin[0], origin[1], origin[2]};
    const Expected e = quake_volumes(source_f, eye, right, 255.0, 1.0);
    for (double v : {e.left, e.right}) {  // keep clear of truncation boundaries
        ASSERT_GT(v - std::floor(v), 0.01);
        ASSERT_LT(v - std::floor(v), 0.99);
    }
    const int left = int(e.left), right_vol = int(e.right);

    for (int f = 0; f < 5; ++f) rig.frame();
    ASSERT_FALSE(rig.client.apply(sound_message(7, 2, 1, origin, 255, 1.0f)));
    for (int f = 0; f < 20; ++f) rig.frame();

    const auto& out = rig.out();
    ASSERT_EQ(out.size(), 25 * kFramesPerFrame);
    const size_t start = 5 * kFramesPerFrame;  // the frame in which the message arrived
    for (size_t i = 0; i < start; ++i) {
        ASSERT_EQ(out[i].left, 0) << i;
        ASSERT_EQ(out[i].right, 0) << i;
    }
    const std::vector<double> wave = upsampled_x4(samples);
    for (size_t i = 0; i < wave.size(); ++i) {
        const double want_l = std::clamp(wave[i] * left / 255.0 * kVolume, -32768.0, 32767.0);
        const double want_r = std::clamp(wave[i] * right_vol / 255.0 * kVolume, -32768.0, 32767.0);
        ASSERT_NEAR(out[start + i].left, want_l, 1.0) << "frame " << i;
        ASSERT_NEAR(out[start + i].right, want_r, 1.0) << "frame " << i;
    }
    for (size_t i = start + wave.size(); i < out.size(); ++i) {  // a one-shot: then silence
        ASSERT_EQ(out[i].left, 0);
        ASSERT_EQ(out[i].right, 0);
    }
}

TEST(SoundMixer, SvcSoundPlaysItsWaveformFromItsFrameSpatializedAsQuake) {
    check_sound_from({310, 123, 0}, "source right of the listener");
    check_sound_from({-277, 41, 0}, "source left of the listener");
    check_sound_from({-57, 611, 0}, "source ahead, far");
}

size_t playing_dynamics(const SoundSystem& s) {
    size_t n = 0;
    for (const SoundChannel& ch : s.mixer().channels().dynamics()) n += ch.sample != nullptr;
    return n;
}

TEST(SoundMixer, SoundsBeyondTheClipDistanceAreNotStartedUnlessUnattenuated) {
    Rig rig;
    test::SynthWav wav;
    wav.samples = pattern(500);
    rig.files["sound/a.wav"] = test::write_wav(wav);
    rig.new_level({"a.wav"});
    rig.listener = listener_for_view({0, 0, 0}, {0, 0, 0}, 1);
    // ATTN_IDLE (2) at 600 units: 1 - 600 * 2 / 1000 < 0 on both sides.
    ASSERT_FALSE(rig.client.apply(sound_message(7, 1, 1, {600, 0, 0}, 255, 2.0f)));
    rig.frame();
    EXPECT_EQ(playing_dynamics(*rig.sound), 0u);
    // ATTN_NONE (0): heard anywhere at full volume in both ears.
    ASSERT_FALSE(rig.client.apply(sound_message(8, 1, 1, {60000, 0, 0}, 255, 0.0f)));
    rig.frame();
    const SoundChannel& ch = rig.sound->mixer().channels().dynamics()[0];
    ASSERT_NE(ch.sample, nullptr);
    EXPECT_EQ(ch.volume.left, 255);
    EXPECT_EQ(ch.volume.right, 255);
}

size_t playing_on(const SoundSystem& s, int entity) {
    size_t n = 0;
    for (const SoundChannel& ch : s.mixer().channels().dynamics())
        n += ch.sample && ch.entity == entity;
    return n;
}

TEST(SoundMixer, ANewSoundOnAnEntityChannelReplacesTheOldOneButChannelZeroNever) {
    Rig rig;
    test::SynthWav wav;
    wav.samples = pattern(5000);
    rig.files["sound/a.wav"] = test::write_wav(wav);
    rig.files["sound/b.wav"] = test::write_wav(wav);
    rig.new_level({"a.wav", "b.wav"});
    ASSERT_FALSE(rig.client.apply(sound_message(9, 3, 1, {0, 0, 0}, 255, 1)));
    ASSERT_FALSE(rig.client.apply(sound_message(9, 3, 2, {0, 0, 0}, 255, 1)));
    rig.frame();
    EXPECT_EQ(playing_on(*rig.sound, 9), 1u);
    ASSERT_FALSE(rig.client.apply(sound_message(9, 4, 1, {0, 0, 0}, 255, 1)));
    ASSERT_FALSE(rig.client.apply(sound_message(10, 0, 1, {0, 0, 0}, 255, 1)));
    ASSERT_FALSE(rig.client.apply(sound_message(10, 0, 2, {0, 0, 0}, 255, 1)));
    rig.frame();
    EXPECT_EQ(playing_on(*rig.sound, 9), 2u);   // another channel of the entity
    EXPECT_EQ(playing_on(*rig.sound, 10), 2u);  // channel 0 never replaces
    svc::StopSound stop;
    stop.entity = 9;
    stop.channel = 3;
    ASSERT_FALSE(rig.client.apply(stop));
    rig.frame();
    EXPECT_EQ(playing_on(*rig.sound, 9), 1u);
}

// Static sounds loop: from the cue point when the WAV has one, from the start when not.
TEST(SoundMixer, StaticSoundsLoop) {
    for (bool cue : {false, true}) {
        SCOPED_TRACE(cue ? "with a cue point" : "without a cue point");
        Rig rig;
        const std::vector<int16_t> samples = pattern(300);  // 1200 output frames
        test::SynthWav wav;
        wav.samples = samples;
        if (cue) wav.loop_start = 100;  // output frame 400
        rig.files["sound/loop.wav"] = test::write_wav(wav);
        rig.new_level({"loop.wav"});
        rig.listener = listener_for_view({0, 0, 0}, {0, 0, 0}, 1);
        svc::SpawnStaticSound s;
        s.fields = {{0, 0, 0}, 1, 255, 3.0f};  // at the listener: dist 0, dot 0
        ASSERT_FALSE(rig.client.apply(s));
        for (int f = 0; f < 10; ++f) rig.frame();
        const auto& out = rig.out();
        const std::vector<double> wave = upsampled_x4(samples);
        const size_t loop_start = cue ? 400 : 0;
        ASSERT_GT(out.size(), 3 * wave.size());
        for (size_t i = 0; i < out.size(); ++i) {
            const size_t pos =
                i < wave.size() ? i : loop_start + (i - wave.size()) % (wave.size() - loop_start);
            ASSERT_NEAR(out[i].left, wave[pos] * kVolume, 1.0) << i;
            ASSERT_NEAR(out[i].right, wave[pos] * kVolume, 1.0) << i;
        }
    }
}

// A leaf of lq1m1 full of water with the given water ambient level, and a point inside it.
struct WaterLeaf {
    BspVec3 point{};
    int level = 0;
};
WaterLeaf find_water_leaf(const Bsp& bsp) {
    for (uint32_t i = 1; i < bsp.leafs.size(); ++i) {
        const BspLeaf& leaf = bsp.leafs[i];
        if (leaf.contents != bsp_contents::water || leaf.ambient_levels[0] < 100) continue;
        BspVec3 c{};
        for (int k = 0; k < 3; ++k) c[k] = (leaf.mins[k] + leaf.maxs[k]) / 2;
        if (leaf_at(bsp, c) == i) return {c, leaf.ambient_levels[0]};
    }
    return {};
}

TEST(SoundMixer, WaterAmbientRisesAtQuakesRateWhenTheListenerIsInAWaterLeaf) {
    auto bytes = read_file(test::lq1_dir() + "/maps/lq1m1.bsp");
    ASSERT_TRUE(bytes);
    auto bsp = parse_bsp(*bytes, "maps/lq1m1.bsp");
    ASSERT_TRUE(bsp) << bsp.error().to_string();
    const WaterLeaf water = find_water_leaf(*bsp);
    ASSERT_GT(water.level, 0) << "lq1m1 has no water leaf with a water ambient";
    const uint32_t dry = leaf_at(*bsp, {0, 0, 0});
    ASSERT_EQ(bsp->leafs[dry].ambient_levels[0], 0);

    Rig rig;
    rig.new_level({});
    rig.sound->set_world(&*bsp);
    rig.listener = listener_for_view({0, 0, 0}, {0, 0, 0}, 1);
    for (int f = 0; f < 5; ++f) rig.frame();
    const SoundChannel& ambient = rig.sound->mixer().channels().ambients()[0];
    ASSERT_NE(ambient.sample, nullptr) << "sound/ambience/water1.wav not loaded";
    EXPECT_EQ(ambient.volume.left, 0);

    rig.listener.origin = {water.point[0], water.point[1], water.point[2]};
    const double target = 0.3 * water.level;  // ambient_level 0.3
    double expected = 0;
    for (int f = 1; f <= 100; ++f) {  // 0.3 * 255 = 76.5 is reached in 77 frames
        rig.frame();
        expected = std::min(target, expected + kFrameTime * 100);  // ambient_fade 100 per second
        ASSERT_EQ(ambient.volume.left, int(expected + 1e-6)) << "frame " << f;
        ASSERT_EQ(ambient.volume.right, ambient.volume.left);
    }
    EXPECT_EQ(ambient.volume.left, int(target));
    // The water is heard: the last frames are not silent.
    const auto& out = rig.out();
    double energy = 0;
    for (size_t i = out.size() - kFramesPerFrame * 10; i < out.size(); ++i) {
        energy += double(out[i].left) * out[i].left;
    }
    EXPECT_GT(std::sqrt(energy / (kFramesPerFrame * 10)), 10.0);

    rig.listener.origin = {0, 0, 0};  // out of the water: it fades away at the same rate
    for (int f = 1; f <= 10; ++f) {
        rig.frame();
        expected = std::max(0.0, expected - kFrameTime * 100);
        ASSERT_EQ(ambient.volume.left, int(expected + 1e-6)) << "frame " << f;
    }
}

TEST(SoundMixer, PauseHoldsEverySoundWhereItIs) {
    Rig rig;
    const std::vector<int16_t> samples = pattern(2000);
    test::SynthWav wav;
    wav.samples = samples;
    rig.files["sound/a.wav"] = test::write_wav(wav);
    rig.new_level({"a.wav"});
    ASSERT_FALSE(rig.client.apply(sound_message(1, 1, 1, {0, 0, 0}, 255, 1)));
    rig.frame();
    for (int f = 0; f < 3; ++f) rig.frame(kFrameTime, true);
    rig.frame();
    const auto& out = rig.out();
    ASSERT_EQ(out.size(), 5 * kFramesPerFrame);
    const std::vector<double> wave = upsampled_x4(samples);
    for (size_t i = 0; i < out.size(); ++i) {
        const bool paused = i >= kFramesPerFrame && i < 4 * kFramesPerFrame;
        const size_t pos = i < kFramesPerFrame ? i : i - 3 * kFramesPerFrame;
        const double want = paused ? 0.0 : wave[pos] * kVolume;  // view entity: full volume
        ASSERT_NEAR(out[i].left, want, 1.0) << i;
    }
}

TEST(SoundMixer, MutedStartsNothingAndMixesSilence) {
    Rig rig;
    test::SynthWav wav;
    wav.samples = pattern(2000);
    rig.files["sound/a.wav"] = test::write_wav(wav);
    rig.new_level({"a.wav"});
    rig.sound->set_muted(true);  // a timedemo without timedemo_sound, or nosound 1
    ASSERT_FALSE(rig.client.apply(sound_message(1, 1, 1, {0, 0, 0}, 255, 1)));
    rig.frame();
    EXPECT_EQ(playing_dynamics(*rig.sound), 0u);
    for (const StereoFrame& f : rig.out()) ASSERT_EQ(f.left, 0);
}

TEST(SoundMixer, MissingSoundsWarnOnceAndTheRestPlay) {
    Rig rig;
    test::SynthWav wav;
    wav.samples = pattern(100);
    rig.files["sound/here.wav"] = test::write_wav(wav);
    rig.printed.clear();
    rig.new_level({"gone.wav", "here.wav"});
    rig.frame();
    rig.new_level({"gone.wav", "here.wav"});
    rig.frame();
    ASSERT_EQ(rig.printed.size(), 1u);
    EXPECT_NE(rig.printed[0].find("sound/gone.wav"), std::string::npos);
    EXPECT_NE(rig.sound->precached(2), nullptr);
    EXPECT_EQ(rig.sound->precached(1), nullptr);
}

TEST(SoundMixer, NoAllocationPerFrameWhileSoundsPlay) {
    Rig rig;
    test::SynthWav wav;
    wav.samples = pattern(20000);
    wav.loop_start = 10;
    rig.files["sound/a.wav"] = test::write_wav(wav);
    rig.new_level({"a.wav"});
    svc::SpawnStaticSound s;
    s.fields = {{100, 0, 0}, 1, 200, 1.0f};
    ASSERT_FALSE(rig.client.apply(s));
    rig.frame();
    const long before = ::nq::test::g_allocations.load();
    for (int f = 0; f < 200; ++f) {
        ASSERT_FALSE(
            rig.client.apply(sound_message(5 + f % 7, 1 + f % 3, 1, {float(f), 20, 0}, 255, 1)));
        rig.listener.origin = {float(f % 50), 0, 0};
        rig.frame();
    }
    EXPECT_EQ(::nq::test::g_allocations.load() - before, 0);
    EXPECT_GT(playing_dynamics(*rig.sound), 1u);
}

}  // namespace
}  // namespace nq
