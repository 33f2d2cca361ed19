// Frame-time statistics for timedemo and -benchjson.
//
// What counts (the QuakeSpasm convention): the first frame of a timedemo carries the time spent
// loading and connecting, so it is excluded from everything - frames, seconds, fps and the
// distribution. QuakeSpasm takes the start time at the beginning of the second frame and
// reports (frames run - 1); recording every frame's duration and dropping the first gives the
// same numbers. (When no time passed QuakeSpasm divides by 1 second; here fps is 0.)
//
// Definitions over the n counted frame times t (milliseconds), sorted ascending:
//   median     the middle value; the mean of the two middle values when n is even
//   p95, p99   nearest rank: the smallest t such that at least 95% (99%) of the frames are no
//              slower, i.e. sorted[ceil(n * p / 100) - 1]
//   1% low fps the average frame rate over the slowest 1% of frames: with k = ceil(n / 100)
//              (at least 1) slowest frames, k / (sum of their seconds). Like the overall fps it
//              is frames over time, not a mean of per-frame rates.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace nq {

struct FrameSummary {
    uint64_t frames = 0;  // counted frames (first excluded)
    double seconds = 0;   // their total duration
    double fps = 0;       // frames / seconds; 0 when no time passed
    double median_ms = 0;
    double p95_ms = 0;
    double p99_ms = 0;
    double low1_fps = 0;
    uint64_t distribution_frames = 0;  // frames behind the percentiles (< frames on overflow)
};

// Storage for per-frame durations, sized before the run so record() never allocates. Frames
// past the capacity still count in frames, seconds and fps, but not in the distribution.
class FrameTimeRecorder {
  public:
    // 2^20 frames (8 MiB): over 17 minutes at 1000 fps.
    static constexpr size_t kDefaultCapacity = size_t{1} << 20;

    explicit FrameTimeRecorder(size_t capacity = kDefaultCapacity);

    // Outside the frame loop only: may allocate. Keeps what was recorded.
    void reserve(size_t capacity);
    void clear();
    void record(double seconds);  // one frame's duration; never allocates

    std::span<const double> stored_seconds() const { return seconds_; }
    uint64_t frames() const { return seconds_.size() + overflow_frames_; }
    size_t capacity() const { return seconds_.capacity(); }

    FrameSummary summarize() const;

  private:
    std::vector<double> seconds_;
    uint64_t overflow_frames_ = 0;
    double overflow_seconds_ = 0;
};

// Summary of a complete list of frame durations (seconds), the first one excluded.
FrameSummary summarize_frames(std::span<const double> frame_seconds);

// Quake's timedemo result line, without newline: "%i frames %5.1f seconds %5.1f fps".
std::string quake_timedemo_line(const FrameSummary& summary);

}  // namespace nq
