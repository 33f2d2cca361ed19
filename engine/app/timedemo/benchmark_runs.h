// -benchmark DEMO -benchmarkruns N: the same timedemo N times in one process, and what is
// reported over the runs: the spread of their frame rates (min / median / max) and the medians
// of their frame-time percentiles, printed and appended as one line to benchmark.log.
// A run that fails ends the benchmark: no figure is reported for it or over the others.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "video/frame_stats.h"

namespace nq {

struct BenchmarkSpread {
    size_t runs = 0;
    double min_fps = 0;
    double median_fps = 0;
    double max_fps = 0;
    double median_ms = 0;  // the runs' medians, percentiles and 1% lows: median over runs
    double p95_ms = 0;
    double p99_ms = 0;
    double low1_fps = 0;
};

// Median over runs (the mean of the middle two for an even count). Empty -> all zero.
BenchmarkSpread spread_of(std::span<const FrameSummary> runs);

// Where the benchmark.log line comes from (besides the figures).
struct BenchmarkContext {
    std::string utc_time;  // ISO 8601, e.g. 2026-12-03T08:45:12Z
    std::string engine_version;
    std::string gl_renderer;
    std::string plugin;
    int width = 0;
    int height = 0;
    std::string command_line;
};

class BenchmarkRuns {
  public:
    BenchmarkRuns(std::string demo, int runs_wanted);

    const std::string& demo() const { return demo_; }
    int runs_wanted() const { return runs_wanted_; }
    size_t runs_done() const { return runs_.size(); }
    bool complete() const { return runs_.size() >= static_cast<size_t>(runs_wanted_); }
    void add_run(const FrameSummary& run) { runs_.push_back(run); }

    // "benchmark demo: 3 runs, fps min 98.1 median 101.3 max 104.0; frame time (median over
    // runs) median 9.81 ms, 95th 12.40 ms, 99th 15.02 ms; 1% low 61.2 fps"
    std::string report() const;
    // One benchmark.log line (no newline): the context, then the report, or "FAILED: why".
    std::string log_line(const BenchmarkContext& context, const std::string& failure) const;

  private:
    std::string demo_;
    int runs_wanted_;
    std::vector<FrameSummary> runs_;
};

// Now, as ISO 8601 UTC.
std::string utc_time_now();
// This process's command line as typed (arguments with spaces quoted), from /proc/self/cmdline.
std::string process_command_line();

}  // namespace nq
