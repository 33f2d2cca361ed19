// The engine's own command-line options, read and validated from a CommandLine.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "host/command_line.h"

namespace nq {

inline constexpr int kMaxWindowDimension = 16384;
inline constexpr int kMaxBenchmarkRuns = 1000;

struct LaunchOptions {
    std::optional<std::string> basedir;       // -basedir DIR: holds the game directories
    std::optional<std::string> game;          // -game DIR: one directory name under basedir
    std::optional<int> width;                 // -width N
    std::optional<int> height;                // -height N
    std::optional<bool> fullscreen;           // -fullscreen / -window (the later one wins)
    std::optional<std::string> bench_json;    // -benchjson FILE: write benchmark results there
    std::optional<std::string> benchmark;     // -benchmark DEMO: time DEMO, report, quit
    int benchmark_runs = 1;                   // -benchmarkruns N: timedemos in one -benchmark
    std::optional<std::string> bench_frames;  // -benchframes FILE: every timedemo's frame times
    std::optional<std::string> bench_trace;   // -benchtrace FILE: per frame, where the time went
    std::vector<std::string> errors;          // one line per unusable option; empty when all fine
};

LaunchOptions read_launch_options(const CommandLine& line);

}  // namespace nq
