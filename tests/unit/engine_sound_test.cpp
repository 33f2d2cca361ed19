// Sound through the engine binary, headless with SDL's disk audio driver (it writes what the
// device plays to a file): a timedemo with timedemo_sound 1 is heard; -nosound opens no
// device at all; a timedemo is silent by default.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

#include "common/file_io.h"
#include "engine_runs.h"
#include "support/engine_run.h"

namespace nq {
namespace {

using namespace test;

struct SoundRun {
    ProcessResult result;
    std::optional<std::vector<uint8_t>> audio;  // what the disk driver wrote, if it wrote
};

SoundRun timedemo_with_disk_audio(const std::string& tag, const std::vector<std::string>& extra) {
    TempDir dir("nq_engine_sound_" + tag);
    std::vector<std::string> args = engine_runs::base_args(dir.path(), data_root(), "lq1");
    args.insert(args.end(), extra.begin(), extra.end());
    args.insert(args.end(), {"+timedemo", "demo2", "+quit"});
    const std::string raw = dir.file("audio.raw");
    SoundRun run;
    run.result =
        run_nprquake(args, dir.path(), 300, {"SDL_AUDIODRIVER=disk", "SDL_DISKAUDIOFILE=" + raw});
    if (std::filesystem::exists(raw)) run.audio = read_file(raw).value();
    return run;
}

size_t loud_samples(const std::vector<uint8_t>& raw) {
    size_t n = 0;
    for (size_t i = 0; i + 1 < raw.size(); i += 2) {
        int16_t s;
        std::memcpy(&s, &raw[i], 2);
        n += std::abs(int(s)) > 64;
    }
    return n;
}

TEST(EngineSound, TimedemoSoundIsHeardThroughTheDiskDriver) {
    SoundRun run = timedemo_with_disk_audio("on", {"+timedemo_sound", "1"});
    ASSERT_EQ(run.result.exit_code, 0) << run.result.describe();
    EXPECT_EQ(sanitizer_report(run.result.err), "");
    EXPECT_EQ(
        lines_containing(run.result.out, "sound: 44100 Hz stereo through SDL's \"disk\"").size(),
        1u)
        << run.result.out;
    ASSERT_TRUE(run.audio) << "the disk driver wrote nothing";
    EXPECT_GT(run.audio->size(), 4096u);
    EXPECT_GT(loud_samples(*run.audio), 1000u);
}

TEST(EngineSound, TimedemoIsSilentByDefault) {
    SoundRun run = timedemo_with_disk_audio("default", {});
    ASSERT_EQ(run.result.exit_code, 0) << run.result.describe();
    ASSERT_TRUE(run.audio) << "the device was opened: the disk driver writes its file";
    EXPECT_EQ(loud_samples(*run.audio), 0u);
}

TEST(EngineSound, NosoundOpensNoDeviceAndMixesNothing) {
    SoundRun run = timedemo_with_disk_audio("off", {"-nosound", "+timedemo_sound", "1"});
    ASSERT_EQ(run.result.exit_code, 0) << run.result.describe();
    EXPECT_EQ(lines_containing(run.result.out, "sound: off (-nosound)").size(), 1u);
    EXPECT_TRUE(lines_containing(run.result.out, "Hz stereo through").empty());
    EXPECT_FALSE(run.audio) << "the disk driver was opened";
    EXPECT_FALSE(lines_containing(run.result.out, " seconds ").empty()) << "no timedemo line";
}

}  // namespace
}  // namespace nq
