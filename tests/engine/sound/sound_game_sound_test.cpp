// The engine's sound wing (sound/game_sound.h) on a memory sink: the output opened on the
// first frame and never with -nosound, a missing device said once and not retried, what is
// played reaching the output, a silent timedemo, and the end of a demo or game stopping every
// sound and the music.
#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "client/client_state.h"
#include "support/render_test_support.h"
#include "sound/game_sound.h"

namespace nq {
namespace {

struct Output {
    int opened = 0;
    MemorySink* sink = nullptr;  // owned by the sound system once opened
    std::vector<std::string> lines;
};

std::unique_ptr<GameSound> make_sound(HostCore& host, Output& out, bool nosound,
                                      bool device = true) {
    auto sound = std::make_unique<GameSound>(
        host, nosound, [&out](std::string_view t) { out.lines.emplace_back(t); },
        [&out, device](int rate, const GameSound::Printer&) -> std::unique_ptr<AudioSink> {
            ++out.opened;
            if (!device) return nullptr;
            auto sink = std::make_unique<MemorySink>(rate);
            out.sink = sink.get();
            return sink;
        });
    sound->set_reader([](const std::string& path) { return render_test::lq1_vfs().read(path); });
    return sound;
}

size_t loud_frames(const MemorySink& sink, size_t from) {
    size_t n = 0;
    for (size_t i = from; i < sink.frames().size(); ++i) {
        n += std::abs(sink.frames()[i].left) > 64 || std::abs(sink.frames()[i].right) > 64;
    }
    return n;
}

TEST(GameSound, NosoundNeverOpensAnOutput) {
    HostCore host;
    Output out;
    auto sound = make_sound(host, out, true);
    for (int i = 0; i < 5; ++i) sound->update(0.02, {});
    EXPECT_EQ(out.opened, 0);
    EXPECT_EQ(sound->system(), nullptr);
    ASSERT_FALSE(out.lines.empty());
    EXPECT_EQ(out.lines.front(), "sound: off (-nosound)");
}

TEST(GameSound, AMissingDeviceIsTriedOnceAndTheEngineGoesOnSilent) {
    HostCore host;
    Output out;
    auto sound = make_sound(host, out, false, false);
    for (int i = 0; i < 5; ++i) sound->update(0.02, {});
    EXPECT_EQ(out.opened, 1);
    EXPECT_EQ(sound->system(), nullptr);
}

TEST(GameSound, PlayedSoundsReachTheOutputAndATimedemoIsSilent) {
    HostCore host;
    Output out;
    auto sound = make_sound(host, out, false);
    sound->update(0.02, {});  // opens
    ASSERT_EQ(out.opened, 1);
    ASSERT_NE(out.sink, nullptr);
    host.commands().add_text("play items/armor1.wav\n");
    host.commands().execute();
    for (int i = 0; i < 10; ++i) sound->update(0.02, {});
    EXPECT_GT(loud_frames(*out.sink, 0), 1000u) << "the played sound is not in the output";

    // A timedemo with timedemo_sound 0 (the default) mutes: what was playing stops.
    ClientState client;
    SoundFrame timedemo;
    timedemo.client = &client;
    timedemo.session = 1;
    timedemo.timedemo = true;
    host.commands().add_text("play items/armor1.wav\n");
    host.commands().execute();
    const size_t before = out.sink->frames().size();
    for (int i = 0; i < 10; ++i) sound->update(0.02, timedemo);
    EXPECT_EQ(loud_frames(*out.sink, before), 0u);
    EXPECT_GT(out.sink->frames().size(), before) << "silence is still written";
    EXPECT_EQ(out.opened, 1) << "opened once";
}

TEST(GameSound, TheEndOfADemoOrGameStopsSoundsAndMusic) {
    HostCore host;
    Output out;
    auto sound = make_sound(host, out, false);
    ClientState client;
    SoundFrame running;
    running.client = &client;
    running.session = 1;
    sound->update(0.02, running);
    ASSERT_NE(sound->system(), nullptr);
    host.commands().add_text("music track03\nplay items/armor1.wav\n");
    host.commands().execute();
    sound->update(0.02, running);
    ASSERT_TRUE(sound->system()->music_playing()) << "music/track03 of the data";
    sound->update(0.02, {});  // the demo or game ended
    EXPECT_FALSE(sound->system()->music_playing());
    const size_t before = out.sink->frames().size();
    sound->update(0.2, {});
    EXPECT_EQ(loud_frames(*out.sink, before), 0u);
}

}  // namespace
}  // namespace nq
