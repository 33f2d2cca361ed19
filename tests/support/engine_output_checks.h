// Reading what nprquake printed: how it ended, and Quake's timedemo line.
#pragma once

#include <gtest/gtest.h>

#include <optional>
#include <regex>
#include <string>
#include <vector>

#include "support/engine_run.h"

namespace nq::test {

// The run started, ended by itself with status 0 within its time limit, and no sanitizer
// (ASan, LSan, UBSan) reported anything.
inline void expect_clean_exit(const ProcessResult& r) {
    ASSERT_TRUE(r.spawned) << r.describe();
    EXPECT_FALSE(r.timed_out) << r.describe();
    EXPECT_EQ(r.signal, 0) << r.describe();
    EXPECT_EQ(r.exit_code, 0) << r.describe();
    EXPECT_EQ(sanitizer_report(r.err), "") << r.describe();
}

// "N frames S seconds F fps", as timedemo prints it.
struct TimedemoLine {
    uint64_t frames = 0;
    double seconds = 0;
    double fps = 0;
};

inline std::vector<TimedemoLine> timedemo_lines(const std::string& stdout_text) {
    static const std::regex line(R"(^(\d+) frames +([0-9.]+) seconds +([0-9.]+) fps$)");
    std::vector<TimedemoLine> out;
    for (const std::string& l : lines_containing(stdout_text, " fps")) {
        std::smatch m;
        if (std::regex_match(l, m, line)) {
            out.push_back({std::stoull(m[1]), std::stod(m[2]), std::stod(m[3])});
        }
    }
    return out;
}

// The line's fps agrees with its frames and seconds (each printed to one decimal).
inline void expect_consistent_fps(const TimedemoLine& t) {
    if (t.seconds < 0.1) return;  // too coarse to compare
    double low = t.frames / (t.seconds + 0.05) - 0.05, high = t.frames / (t.seconds - 0.05) + 0.05;
    EXPECT_GE(t.fps, low) << t.frames << " frames in " << t.seconds << " s";
    EXPECT_LE(t.fps, high) << t.frames << " frames in " << t.seconds << " s";
}

}  // namespace nq::test
