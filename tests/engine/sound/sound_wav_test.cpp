// WAV loading as Quake reads it (cue loop start, ltxt "mark" loop length), resampling to the
// output rate, and untrusted files: a clear warning naming file, offset and problem, then
// silence.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>

#include "common/file_io.h"
#include "sound/sound_system.h"
#include "sound/wav.h"
#include "support/synth_wav.h"
#include "support/test_data.h"

namespace nq {
namespace {

using test::SynthWav;
using test::write_wav;

std::vector<int16_t> pattern(size_t n) {
    std::vector<int16_t> s(n);
    for (size_t i = 0; i < n; ++i) s[i] = int16_t((int(i) * 1237) % 30001 - 15000);
    return s;
}

TEST(SoundWav, Reads16BitMonoAsStored) {
    SynthWav w;
    w.samples = pattern(100);
    auto wav = parse_wav(write_wav(w), "a.wav");
    ASSERT_TRUE(wav) << wav.error().to_string();
    EXPECT_EQ(wav->rate, 11025);
    EXPECT_EQ(wav->bits, 16);
    EXPECT_EQ(wav->loop_start, -1);
    EXPECT_EQ(wav->samples, w.samples);
}

TEST(SoundWav, Reads8BitAsUnsignedAround128) {
    SynthWav w;
    w.bits = 8;
    w.samples = pattern(50);
    const std::vector<uint8_t> file = write_wav(w);
    auto wav = parse_wav(file, "b.wav");
    ASSERT_TRUE(wav) << wav.error().to_string();
    ASSERT_EQ(wav->samples.size(), 50u);
    // The data chunk is the last 50 bytes of the file.
    for (size_t i = 0; i < 50; ++i) {
        EXPECT_EQ(wav->samples[i], (int(file[file.size() - 50 + i]) - 128) * 256) << i;
    }
}

TEST(SoundWav, LoopStartFromCueAndLoopEndFromMark) {
    SynthWav w;
    w.samples = pattern(100);
    w.loop_start = 20;
    w.loop_length = 50;
    auto wav = parse_wav(write_wav(w), "loop.wav");
    ASSERT_TRUE(wav) << wav.error().to_string();
    EXPECT_EQ(wav->loop_start, 20);
    // Quake plays up to loop start + loop length and no further.
    ASSERT_EQ(wav->samples.size(), 70u);
    EXPECT_TRUE(std::equal(wav->samples.begin(), wav->samples.end(), w.samples.begin()));
}

TEST(SoundWav, StereoIsMixedDownToMono) {
    SynthWav w;
    w.channels = 2;
    w.samples = {1000, 3000, -2000, -4000, 7, 8};
    auto wav = parse_wav(write_wav(w), "s.wav");
    ASSERT_TRUE(wav) << wav.error().to_string();
    EXPECT_EQ(wav->samples, (std::vector<int16_t>{2000, -3000, 7}));
}

TEST(SoundWav, MalformedFilesNameFileOffsetAndProblem) {
    SynthWav w;
    w.samples = pattern(10);
    std::vector<uint8_t> not_riff = write_wav(w);
    not_riff[0] = 'X';
    auto a = parse_wav(not_riff, "sound/x.wav");
    ASSERT_FALSE(a);
    EXPECT_EQ(a.error().file, "sound/x.wav");
    EXPECT_EQ(a.error().offset, 0u);
    EXPECT_NE(a.error().message.find("RIFF"), std::string::npos);

    SynthWav adpcm = w;
    adpcm.format = 2;
    auto b = parse_wav(write_wav(adpcm), "sound/y.wav");
    ASSERT_FALSE(b);
    EXPECT_EQ(b.error().offset, 20u);  // RIFF header 12 + fmt chunk header 8: the format tag
    EXPECT_NE(b.error().message.find("not PCM"), std::string::npos);

    SynthWav long_loop = w;
    long_loop.loop_start = 2;
    long_loop.loop_length = 100;
    auto c = parse_wav(write_wav(long_loop), "sound/z.wav");
    ASSERT_FALSE(c);
    // 12 + fmt (8 + 16) + cue (8 + 28) = 72: the LIST chunk's header, 80 its data, +16 the length.
    EXPECT_EQ(c.error().offset, 96u);
    EXPECT_NE(c.error().message.find("loop length 100"), std::string::npos);

    SynthWav late_loop = w;
    late_loop.loop_start = 50;  // past the 10 samples
    auto d = parse_wav(write_wav(late_loop), "sound/u.wav");
    ASSERT_FALSE(d);
    // The cue chunk's data starts at 44; its first point's sample offset is 24 bytes in.
    EXPECT_EQ(d.error().offset, 68u);
    EXPECT_NE(d.error().message.find("loop start 50"), std::string::npos);

    SynthWav no_fmt = w;
    no_fmt.write_fmt = false;
    EXPECT_FALSE(parse_wav(write_wav(no_fmt), "sound/w.wav"));
    std::vector<uint8_t> cut = write_wav(w);
    cut.resize(10);
    EXPECT_FALSE(parse_wav(cut, "sound/v.wav"));
}

TEST(SoundWav, ResamplesLinearlyToTheOutputRate) {
    WavSound wav;
    wav.rate = 11025;
    wav.samples = pattern(40);
    wav.loop_start = 10;
    SoundSample s = resample(wav, 44100);
    ASSERT_EQ(s.length(), 160u);  // four output frames per input sample
    EXPECT_EQ(s.loop_start, 40);
    for (size_t i = 0; i < s.length(); ++i) {
        const size_t j = i / 4;
        const double f = double(i % 4) / 4.0;
        const double next = j + 1 < 40 ? wav.samples[j + 1] : wav.samples[j];
        const double want = wav.samples[j] * (1 - f) + next * f;
        EXPECT_NEAR(s.frames[i], want, 0.5) << i;
    }
}

// Every sound LibreQuake ships parses (the game's data is the first untrusted input).
TEST(SoundWav, EveryLibreQuakeSoundParses) {
    size_t count = 0;
    for (const auto& entry :
         std::filesystem::recursive_directory_iterator(test::lq1_dir() + "/sound")) {
        if (entry.path().extension() != ".wav") continue;
        auto bytes = read_file(entry.path().string());
        ASSERT_TRUE(bytes) << entry.path();
        auto wav = parse_wav(*bytes, entry.path().string());
        EXPECT_TRUE(wav) << wav.error().to_string();
        if (wav) {
            EXPECT_GT(wav->samples.size(), 0u) << entry.path();
        }
        ++count;
    }
    EXPECT_GT(count, 100u);
}

struct Captured {
    std::vector<std::string> lines;
    SoundPrinter printer() {
        return [this](std::string_view t) { lines.emplace_back(t); };
    }
};

TEST(SoundWav, CorruptWavWarnsOnceAndPlaysSilence) {
    SynthWav w;
    w.samples = pattern(2000);
    std::vector<uint8_t> corrupt = write_wav(w);
    corrupt[20] = 3;  // the format tag: not PCM
    std::map<std::string, std::vector<uint8_t>> files{{"sound/bad.wav", corrupt}};
    Captured out;
    SoundSystem sound(
        std::make_unique<MemorySink>(kOutputRate),
        [&](const std::string& path) -> Result<std::vector<uint8_t>> {
            if (auto it = files.find(path); it != files.end()) return it->second;
            return Error{path, 0, "no such file"};
        },
        out.printer());
    out.lines.clear();  // the ambient sounds' own warnings (not in this file set)
    const std::vector<std::string> names{"", "bad.wav"};
    sound.precache(names);
    ASSERT_EQ(out.lines.size(), 1u);
    EXPECT_NE(out.lines[0].find("sound/bad.wav"), std::string::npos) << out.lines[0];
    EXPECT_NE(out.lines[0].find("offset 20"), std::string::npos) << out.lines[0];
    EXPECT_NE(out.lines[0].find("not PCM"), std::string::npos) << out.lines[0];
    sound.precache(names);  // the next level names it again: no second warning
    EXPECT_EQ(out.lines.size(), 1u);

    sound.start_sound(1, 1, 1, {0, 0, 0}, 1.0f, 0.0f);
    sound.update(0.05, false, SoundSettings{});
    const auto& frames = static_cast<const MemorySink&>(sound.sink()).frames();
    ASSERT_EQ(frames.size(), size_t(std::lround(0.05 * kOutputRate)));
    for (const StereoFrame& f : frames) {
        ASSERT_EQ(f.left, 0);
        ASSERT_EQ(f.right, 0);
    }
    EXPECT_EQ(sound.mixer().channels().active_count(), 0u);
}

}  // namespace
}  // namespace nq
