#include "video/frame_stats.h"

#include <algorithm>
#include <cstdio>
#include <numeric>

namespace nq {
namespace {

double median_of_sorted(std::span<const double> sorted) {
    size_t n = sorted.size();
    if (n % 2 == 1) return sorted[n / 2];
    return (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
}

// Integer arithmetic keeps ceil(n * percent / 100) exact.
double nearest_rank(std::span<const double> sorted, size_t percent) {
    size_t rank = (sorted.size() * percent + 99) / 100;
    return sorted[std::max<size_t>(rank, 1) - 1];
}

double low1_fps_of_sorted(std::span<const double> sorted) {
    size_t k = std::max<size_t>((sorted.size() + 99) / 100, 1);
    double slowest = std::accumulate(sorted.end() - static_cast<ptrdiff_t>(k), sorted.end(), 0.0);
    return slowest > 0 ? static_cast<double>(k) / slowest : 0.0;
}

void fill_distribution(FrameSummary& s, std::vector<double> sorted_seconds) {
    std::sort(sorted_seconds.begin(), sorted_seconds.end());
    s.distribution_frames = sorted_seconds.size();
    if (sorted_seconds.empty()) return;
    s.median_ms = median_of_sorted(sorted_seconds) * 1000;
    s.p95_ms = nearest_rank(sorted_seconds, 95) * 1000;
    s.p99_ms = nearest_rank(sorted_seconds, 99) * 1000;
    s.low1_fps = low1_fps_of_sorted(sorted_seconds);
}

// Summary of the counted frames plus frames that were timed but not stored.
FrameSummary summarize_counted(std::span<const double> counted, uint64_t extra_frames,
                               double extra_seconds) {
    FrameSummary s;
    s.frames = counted.size() + extra_frames;
    s.seconds = std::accumulate(counted.begin(), counted.end(), 0.0) + extra_seconds;
    s.fps = s.seconds > 0 ? static_cast<double>(s.frames) / s.seconds : 0.0;
    fill_distribution(s, std::vector<double>(counted.begin(), counted.end()));
    return s;
}

}  // namespace

// At least one slot, so the first frame (the one excluded) is always stored.
FrameTimeRecorder::FrameTimeRecorder(size_t capacity) {
    reserve(capacity);
}

void FrameTimeRecorder::reserve(size_t capacity) {
    seconds_.reserve(std::max<size_t>(capacity, 1));
}

void FrameTimeRecorder::clear() {
    seconds_.clear();
    overflow_frames_ = 0;
    overflow_seconds_ = 0;
}

void FrameTimeRecorder::record(double seconds) {
    if (seconds_.size() < seconds_.capacity()) {
        seconds_.push_back(seconds);  // within capacity: no allocation
        return;
    }
    ++overflow_frames_;
    overflow_seconds_ += seconds;
}

FrameSummary FrameTimeRecorder::summarize() const {
    if (seconds_.empty()) return FrameSummary{};
    return summarize_counted(std::span<const double>(seconds_).subspan(1), overflow_frames_,
                             overflow_seconds_);
}

FrameSummary summarize_frames(std::span<const double> frame_seconds) {
    if (frame_seconds.empty()) return FrameSummary{};
    return summarize_counted(frame_seconds.subspan(1), 0, 0.0);
}

std::string quake_timedemo_line(const FrameSummary& summary) {
    char line[96];
    std::snprintf(line, sizeof line, "%i frames %5.1f seconds %5.1f fps",
                  static_cast<int>(summary.frames), summary.seconds, summary.fps);
    return line;
}

}  // namespace nq
