// Sound through the engine binary, headless with SDL's disk audio driver (it writes what the
// device plays to a file): a timedemo with timedemo_sound 1 is heard; -nosound opens no
// device at all; a timedemo is silent by default; `playdemo demo` is heard, its first sound
// where the demo's own clock puts it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>

#include "common/file_io.h"
#include "formats/demo_summary.h"
#include "sound/sound_system.h"
#include "support/engine_run.h"
#include "support/engine_runs.h"
#include "support/test_data.h"

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
    // Sound alone is measured: the null renderer draws nothing, so the run costs the demo's
    // client and mixer time, not llvmpipe's.
    args.insert(args.end(), {"+r_plugin", "null", "+timedemo", "demo2", "+quit"});
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

// When demo.dem's first sound plays, from its raw bytes: the svc_time of the frame that
// carries the first svc_sound whose file is in the data, and the demo's last svc_time.
struct FirstSound {
    float time = -1;
    float last_time = -1;
    std::string name;
};

FirstSound first_sound_of(const std::string& demo) {
    FirstSound first;
    auto bytes = read_file(lq1_dir() + "/" + demo + ".dem");
    if (!bytes) return first;
    auto decoded = decode_demo(*bytes, demo + ".dem");
    if (!decoded) return first;
    const DemoSummary summary = summarize_demo(*decoded, demo + ".dem");
    float now = -1;
    for (const DecodedBlock& block : decoded->blocks) {
        for (const DecodedMessage& m : block.messages) {
            if (const auto* t = std::get_if<svc::Time>(&m.message)) now = t->time;
            const auto* sound = std::get_if<svc::Sound>(&m.message);
            if (!sound || first.time >= 0 || now < 0) continue;
            const size_t index = size_t(sound->sound);
            if (index == 0 || index > summary.sounds.size()) continue;
            const std::string& name = summary.sounds[index - 1];
            if (!std::filesystem::exists(lq1_dir() + "/sound/" + name)) continue;
            first.time = now;
            first.name = name;
        }
    }
    first.last_time = summary.last_time.value_or(-1);
    return first;
}

// Seconds from the start of 16-bit stereo `raw` to the first 10 ms whose RMS passes `level`.
double onset_seconds(const std::vector<uint8_t>& raw, int rate, double level) {
    const size_t window = size_t(rate / 100) * 2;  // values of 10 ms, both channels
    const size_t values = raw.size() / 2;
    for (size_t start = 0; start + window <= values; start += window) {
        double sum = 0;
        for (size_t i = start; i < start + window; ++i) {
            int16_t s;
            std::memcpy(&s, &raw[2 * i], 2);
            sum += double(s) * s;
        }
        if (std::sqrt(sum / double(window)) > level) return double(start / 2) / rate;
    }
    return -1;
}

TEST(EngineSound, PlaydemoIsHeardWhenTheDemoReachesItsFirstSound) {
    const FirstSound first = first_sound_of("demo");
    ASSERT_GE(first.time, 0) << "demo.dem has no svc_sound of a sound file in the data";
    ASSERT_GT(first.last_time, first.time);
    TempDir dir("nq_engine_sound_playdemo");
    std::vector<std::string> args = engine_runs::base_args(dir.path(), data_root(), "lq1");
    // Music off: only the demo's sound effects are measured. +quit runs when the demo ends.
    args.insert(args.end(), {"+bgmvolume", "0", "+playdemo", "demo", "+quit"});
    const std::string raw = dir.file("audio.raw");
    ProcessResult r =
        run_nprquake(args, dir.path(), 300, {"SDL_AUDIODRIVER=disk", "SDL_DISKAUDIOFILE=" + raw});
    ASSERT_EQ(r.exit_code, 0) << r.describe();
    EXPECT_EQ(sanitizer_report(r.err), "");
    ASSERT_EQ(lines_containing(r.out, "through SDL's \"disk\" driver").size(), 1u) << r.out;
    auto audio = read_file(raw);
    ASSERT_TRUE(audio) << "the disk driver wrote nothing";
    const double file_seconds = double(audio->size()) / 4 / kOutputRate;
    // The driver writes in real time and the engine quits when the demo ends, so the demo's
    // last svc_time lies at the file's end: the first sound lies (last - first) before it.
    const double expected = file_seconds - (first.last_time - first.time);
    const double onset = onset_seconds(*audio, kOutputRate, 300);
    ASSERT_GE(onset, 0) << "silent: no 10 ms of the " << file_seconds << " s written is loud";
    EXPECT_NEAR(onset, expected, 0.4) << first.name << " at demo time " << first.time;
    EXPECT_GT(loud_samples(*audio), size_t(kOutputRate));  // a second's worth at least
}

}  // namespace
}  // namespace nq
