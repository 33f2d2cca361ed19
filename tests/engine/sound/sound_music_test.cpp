// Music: Ogg Vorbis (libvorbisfile) and WAV tracks decoded in chunks, resampled to the output
// rate, looping or not; the CD track a level asks for (svc_cdtrack) and the music commands.
// Durations are checked against the files' own headers, read here without libvorbis.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "common/file_io.h"
#include "host/host_core.h"
#include "sound/client_sound_feed.h"
#include "sound/music_stream.h"
#include "sound/sound_commands.h"
#include "sound/sound_system.h"
#include "support/synth_wav.h"
#include "support/test_data.h"

namespace nq {
namespace {

uint64_t le(const std::vector<uint8_t>& b, size_t at, int bytes) {
    uint64_t v = 0;
    for (int i = bytes - 1; i >= 0; --i) v = v << 8 | b.at(at + size_t(i));
    return v;
}

// The sample rate (identification header) and the last page's granule position (the stream's
// length in samples), walking the Ogg pages.
struct OggFacts {
    uint64_t rate = 0;
    uint64_t samples = 0;
};
OggFacts read_ogg_facts(const std::vector<uint8_t>& b) {
    OggFacts facts;
    size_t pos = 0;
    while (pos + 27 <= b.size()) {
        EXPECT_EQ(std::string(b.begin() + long(pos), b.begin() + long(pos) + 4), "OggS");
        const uint64_t granule = le(b, pos + 6, 8);
        const size_t segments = b.at(pos + 26);
        size_t body = 0;
        for (size_t s = 0; s < segments; ++s) body += b.at(pos + 27 + s);
        const size_t body_at = pos + 27 + segments;
        if (pos == 0) facts.rate = le(b, body_at + 12, 4);  // "\1vorbis", version, channels
        if (granule != ~uint64_t(0)) facts.samples = granule;
        pos = body_at + body;
    }
    EXPECT_EQ(pos, b.size());
    return facts;
}

// Decodes the whole stream (it must not loop) at 44.1 kHz; returns frames and RMS of the left.
struct Decoded {
    size_t frames = 0;
    double rms = 0;
};
Decoded decode_all(MusicStream& music) {
    std::vector<float> mix(2 * 4096);
    Decoded d;
    double energy = 0;
    for (;;) {
        std::fill(mix.begin(), mix.end(), 0.0f);
        const size_t n = music.paint(mix, 4096, 1.0f);
        for (size_t i = 0; i < n; ++i) energy += double(mix[2 * i]) * mix[2 * i];
        d.frames += n;
        if (n < 4096) break;
    }
    d.rms = d.frames ? std::sqrt(energy / double(d.frames)) : 0;
    return d;
}

TEST(SoundMusic, OggTrackDecodesToItsDurationAndIsNotSilent) {
    const std::string path = test::lq1_dir() + "/music/track03.ogg";
    auto bytes = read_file(path);
    ASSERT_TRUE(bytes) << path;
    const OggFacts facts = read_ogg_facts(*bytes);
    ASSERT_EQ(facts.rate, 48000u);
    ASSERT_GT(facts.samples, 48000u);
    auto source = open_ogg(*bytes, "music/track03.ogg");
    ASSERT_TRUE(source) << source.error().to_string();
    EXPECT_EQ((*source)->total_frames(), facts.samples);
    MusicStream music(std::move(source.value()), kOutputRate, false);
    const Decoded d = decode_all(music);
    const double expected = double(facts.samples) * kOutputRate / double(facts.rate);
    EXPECT_NEAR(double(d.frames), expected, 2.0);
    EXPECT_TRUE(music.ended());
    EXPECT_GT(d.rms, 300.0);
}

TEST(SoundMusic, WavTrackDecodesToItsDurationAndLoopsWhenAsked) {
    test::SynthWav wav;
    wav.rate = 22050;
    for (int i = 0; i < 30000; ++i) wav.samples.push_back(int16_t(8000 * std::sin(i * 0.05)));
    const std::vector<uint8_t> file = test::write_wav(wav);
    auto once = open_wav_music(file, "music/track02.wav");
    ASSERT_TRUE(once) << once.error().to_string();
    MusicStream music(std::move(once.value()), kOutputRate, false);
    const Decoded d = decode_all(music);
    EXPECT_NEAR(double(d.frames), 30000.0 * 2, 2.0);  // 22050 -> 44100 Hz
    EXPECT_NEAR(d.rms, 8000 / std::sqrt(2.0), 100.0);

    auto looped = open_wav_music(file, "music/track02.wav");
    ASSERT_TRUE(looped);
    MusicStream loop(std::move(looped.value()), kOutputRate, true);
    std::vector<float> mix(2 * 4096);
    size_t total = 0;
    for (int i = 0; i < 50; ++i) total += loop.paint(mix, 4096, 1.0f);  // over three times
    EXPECT_EQ(total, 50u * 4096);
    EXPECT_FALSE(loop.ended());
}

struct MusicRig {
    std::vector<std::string> printed;
    SoundSystem sound{std::make_unique<MemorySink>(kOutputRate),
                      [](const std::string& p) { return read_file(test::lq1_dir() + "/" + p); },
                      [this](std::string_view t) { printed.emplace_back(t); }};
};

TEST(SoundMusic, TheLevelsCdTrackPlaysAndAMissingOneIsOneMessage) {
    MusicRig rig;
    ClientState client;
    ClientSoundFeed feed;
    svc::ServerInfo info;
    info.protocol = 15;
    info.max_clients = 1;
    info.models = {"maps/lq1m1.bsp"};
    ASSERT_FALSE(client.apply(info));
    ASSERT_FALSE(client.apply(svc::CdTrack{3, 3}));
    feed.feed(client, rig.sound, {});
    EXPECT_EQ(rig.sound.music_name(), "music/track03");
    EXPECT_TRUE(rig.sound.music_playing());
    rig.sound.update(0.5, false, SoundSettings{});
    const auto& out = static_cast<const MemorySink&>(rig.sound.sink()).frames();
    double energy = 0;
    for (const StereoFrame& f : out) energy += double(f.left) * f.left;
    EXPECT_GT(std::sqrt(energy / double(out.size())), 100.0);

    rig.printed.clear();
    ASSERT_FALSE(client.apply(svc::CdTrack{7, 7}));
    feed.feed(client, rig.sound, {});
    ASSERT_FALSE(client.apply(svc::CdTrack{7, 7}));
    feed.feed(client, rig.sound, {});
    EXPECT_FALSE(rig.sound.music_playing());
    ASSERT_EQ(rig.printed.size(), 1u);
    EXPECT_NE(rig.printed[0].find("music/track07"), std::string::npos);
}

TEST(SoundMusic, CommandsPlayPauseResumeStopAndLoop) {
    MusicRig rig;
    HostCore host;
    std::vector<std::string> console;
    host.set_print([&](std::string_view t) { console.emplace_back(t); });
    register_sound_cvars(host.cvars());
    register_sound_commands(host.commands(), [&] { return &rig.sound; });
    auto run = [&](const char* text) {
        host.commands().add_text(std::string(text) + "\n");
        host.commands().execute();
    };
    run("music track03");
    ASSERT_TRUE(rig.sound.music_playing());
    EXPECT_TRUE(rig.sound.mixer().music()->loop());
    run("music_loop 0");
    EXPECT_FALSE(rig.sound.mixer().music()->loop());
    run("music_pause");
    EXPECT_TRUE(rig.sound.mixer().music_paused());
    rig.sound.update(0.1, false, SoundSettings{});
    for (const StereoFrame& f : static_cast<const MemorySink&>(rig.sound.sink()).frames()) {
        ASSERT_EQ(f.left, 0);  // paused music is silent
    }
    run("music_resume");
    EXPECT_FALSE(rig.sound.mixer().music_paused());
    run("music_stop");
    EXPECT_FALSE(rig.sound.music_playing());
    run("cd play 3");
    EXPECT_EQ(rig.sound.music_name(), "music/track03");
    EXPECT_FALSE(rig.sound.mixer().music()->loop());
    run("cd stop");
    EXPECT_FALSE(rig.sound.music_playing());
}

}  // namespace
}  // namespace nq
