// The -benchjson record: one JSON object per timedemo run, appended to a JSON Lines file.
//
// Fields: demo, plugin, resolution ("WxH"), width, height, gl_renderer, gl_version, frames,
// seconds, fps, median_ms, p95_ms, p99_ms, low1_fps, distribution_frames (see frame_stats.h for
// the definitions), gpu_timing (false when the driver cannot time passes: then gpu_passes is
// empty), gpu_frames, and gpu_passes: {"<pass>": {"total_ms", "ms_per_frame", "count"}, ...}.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "video/frame_stats.h"
#include "video/gpu_pass_totals.h"

namespace nq {

struct BenchRecord {
    std::string demo;    // as given to timedemo, e.g. "demo1"
    std::string plugin;  // renderer plugin name
    int width = 0;       // rendered resolution in pixels
    int height = 0;
    std::string gl_renderer;
    std::string gl_version;
    FrameSummary frames;
    bool gpu_timing = false;
    uint64_t gpu_frames = 0;  // frames the GPU timers covered
    std::vector<GpuPassTotals> gpu_passes;
};

// The record as one line of compact JSON, without the trailing newline.
std::string bench_record_json(const BenchRecord& record);

// Appends the record and a newline to `path` (created if missing). Empty string on success,
// otherwise a message naming the path.
std::string append_bench_record(const std::string& path, const BenchRecord& record);

}  // namespace nq
