// Per-pass GPU time over a run, as reported by timedemo and -benchjson.
#pragma once

#include <cstdint>
#include <string>

namespace nq {

struct GpuPassTotals {
    std::string name;
    double total_ms = 0;      // GPU time spent in the pass over the whole run
    double ms_per_frame = 0;  // total_ms / frames timed (frames without the pass count as 0)
    uint64_t count = 0;       // how many times the pass ran
};

}  // namespace nq
