// Timedemo statistics on synthetic frame times whose answers are worked out by hand.
#include <gtest/gtest.h>

#include <vector>

#include "video/frame_stats.h"

namespace nq {
namespace {

// A 5-second loading frame (excluded, as QuakeSpasm excludes it), then 1, 2, ... 200 ms in a
// scrambled order (37 is coprime with 200, so i*37 mod 200 visits every value once).
std::vector<double> loading_frame_then_1_to_200_ms() {
    std::vector<double> seconds{5.0};
    for (int i = 0; i < 200; ++i) seconds.push_back(((i * 37) % 200 + 1) / 1000.0);
    return seconds;
}

TEST(VideoFrameStats, FirstFrameIsExcludedFromCountsAndTime) {
    FrameSummary s = summarize_frames(loading_frame_then_1_to_200_ms());
    EXPECT_EQ(s.frames, 200u);
    EXPECT_NEAR(s.seconds, 20.1, 1e-9);  // 1 + 2 + ... + 200 = 20100 ms
    EXPECT_NEAR(s.fps, 200 / 20.1, 1e-9);
    EXPECT_EQ(s.distribution_frames, 200u);
}

TEST(VideoFrameStats, PercentilesAndOnePercentLow) {
    FrameSummary s = summarize_frames(loading_frame_then_1_to_200_ms());
    EXPECT_NEAR(s.median_ms, 100.5, 1e-9);  // even count: mean of the 100th and 101st
    EXPECT_NEAR(s.p95_ms, 190.0, 1e-9);     // rank ceil(200 * 0.95) = 190
    EXPECT_NEAR(s.p99_ms, 198.0, 1e-9);     // rank ceil(200 * 0.99) = 198
    // Slowest 1% = 2 frames of 199 and 200 ms: 2 frames in 0.399 s.
    EXPECT_NEAR(s.low1_fps, 2 / 0.399, 1e-9);
}

TEST(VideoFrameStats, NearestRankRoundsUp) {
    std::vector<double> seconds{1.0};
    for (int ms = 1; ms <= 101; ++ms) seconds.push_back(ms / 1000.0);
    FrameSummary s = summarize_frames(seconds);
    EXPECT_NEAR(s.median_ms, 51.0, 1e-9);                // odd count: the middle one
    EXPECT_NEAR(s.p95_ms, 96.0, 1e-9);                   // ceil(95.95) = 96
    EXPECT_NEAR(s.p99_ms, 100.0, 1e-9);                  // ceil(99.99) = 100
    EXPECT_NEAR(s.low1_fps, 2 / (0.100 + 0.101), 1e-9);  // ceil(1.01) = 2 frames

    seconds.pop_back();  // 1..100 ms: exact ranks
    s = summarize_frames(seconds);
    EXPECT_NEAR(s.p95_ms, 95.0, 1e-9);
    EXPECT_NEAR(s.p99_ms, 99.0, 1e-9);
    EXPECT_NEAR(s.low1_fps, 1 / 0.100, 1e-9);  // one frame is the slowest 1%
}

TEST(VideoFrameStats, ThreeFrames) {
    FrameSummary s = summarize_frames(std::vector<double>{1.0, 0.004, 0.001, 0.003});
    EXPECT_EQ(s.frames, 3u);
    EXPECT_NEAR(s.seconds, 0.008, 1e-12);
    EXPECT_NEAR(s.fps, 375.0, 1e-9);
    EXPECT_NEAR(s.median_ms, 3.0, 1e-9);
    EXPECT_NEAR(s.p95_ms, 4.0, 1e-9);
    EXPECT_NEAR(s.p99_ms, 4.0, 1e-9);
    EXPECT_NEAR(s.low1_fps, 250.0, 1e-9);
}

TEST(VideoFrameStats, NothingCountedGivesZeros) {
    for (const std::vector<double>& seconds : {std::vector<double>{}, std::vector<double>{2.0}}) {
        FrameSummary s = summarize_frames(seconds);
        EXPECT_EQ(s.frames, 0u);
        EXPECT_EQ(s.seconds, 0.0);
        EXPECT_EQ(s.fps, 0.0);
        EXPECT_EQ(s.median_ms, 0.0);
        EXPECT_EQ(s.low1_fps, 0.0);
        EXPECT_EQ(quake_timedemo_line(s), "0 frames   0.0 seconds   0.0 fps");
    }
}

TEST(VideoFrameStats, QuakeLineFormat) {
    EXPECT_EQ(quake_timedemo_line(summarize_frames(loading_frame_then_1_to_200_ms())),
              "200 frames  20.1 seconds  10.0 fps");  // 9.95 fps rounds to 10.0
    FrameSummary s;
    s.frames = 1234;
    s.seconds = 56.789;
    s.fps = 1234 / 56.789;  // 21.73
    EXPECT_EQ(quake_timedemo_line(s), "1234 frames  56.8 seconds  21.7 fps");
    s.frames = 100000;
    s.seconds = 100.04;
    s.fps = 999.6;
    EXPECT_EQ(quake_timedemo_line(s), "100000 frames 100.0 seconds 999.6 fps");
}

TEST(VideoFrameStats, RecorderMatchesSummarizeFrames) {
    FrameTimeRecorder recorder(1000);
    std::vector<double> seconds = loading_frame_then_1_to_200_ms();
    for (double t : seconds) recorder.record(t);
    FrameSummary a = recorder.summarize(), b = summarize_frames(seconds);
    EXPECT_EQ(a.frames, b.frames);
    EXPECT_EQ(a.seconds, b.seconds);
    EXPECT_EQ(a.median_ms, b.median_ms);
    EXPECT_EQ(a.p99_ms, b.p99_ms);
    EXPECT_EQ(a.low1_fps, b.low1_fps);
    EXPECT_EQ(recorder.frames(), 201u);
}

TEST(VideoFrameStats, RecordingWithinCapacityNeverReallocates) {
    FrameTimeRecorder recorder(500);
    const double* storage = recorder.stored_seconds().data();
    size_t capacity = recorder.capacity();
    recorder.record(1.0);
    storage = recorder.stored_seconds().data();
    for (int i = 1; i < 500; ++i) recorder.record(0.01);
    EXPECT_EQ(recorder.stored_seconds().data(), storage);
    EXPECT_EQ(recorder.capacity(), capacity);
    recorder.record(0.01);  // past capacity: counted, not stored, still no reallocation
    EXPECT_EQ(recorder.stored_seconds().data(), storage);
    EXPECT_EQ(recorder.stored_seconds().size(), 500u);
    EXPECT_EQ(recorder.frames(), 501u);
}

TEST(VideoFrameStats, FramesPastCapacityCountInTotalsNotInTheDistribution) {
    FrameTimeRecorder recorder(3);
    for (double t : {1.0, 0.010, 0.020, 0.030, 0.040}) recorder.record(t);
    FrameSummary s = recorder.summarize();
    EXPECT_EQ(s.frames, 4u);
    EXPECT_NEAR(s.seconds, 0.100, 1e-12);
    EXPECT_NEAR(s.fps, 40.0, 1e-9);
    EXPECT_EQ(s.distribution_frames, 2u);
    EXPECT_NEAR(s.median_ms, 15.0, 1e-9);

    recorder.clear();
    EXPECT_EQ(recorder.frames(), 0u);
    EXPECT_EQ(recorder.summarize().frames, 0u);
}

}  // namespace
}  // namespace nq
