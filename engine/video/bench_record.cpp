#include "video/bench_record.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include "common/json_writer.h"

namespace nq {
namespace {

void write_frame_fields(JsonWriter& json, const FrameSummary& f) {
    json.field("frames", f.frames);
    json.field("seconds", f.seconds);
    json.field("fps", f.fps);
    json.field("median_ms", f.median_ms);
    json.field("p95_ms", f.p95_ms);
    json.field("p99_ms", f.p99_ms);
    json.field("low1_fps", f.low1_fps);
    json.field("distribution_frames", f.distribution_frames);
}

void write_gpu_fields(JsonWriter& json, const BenchRecord& r) {
    json.field("gpu_timing", r.gpu_timing);
    json.field("gpu_frames", r.gpu_frames);
    json.key("gpu_passes").begin_object();
    if (r.gpu_timing) {
        for (const GpuPassTotals& pass : r.gpu_passes) {
            json.key(pass.name).begin_object();
            json.field("total_ms", pass.total_ms);
            json.field("ms_per_frame", pass.ms_per_frame);
            json.field("count", pass.count);
            json.end_object();
        }
    }
    json.end_object();
}

struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
};

}  // namespace

std::string bench_record_json(const BenchRecord& r) {
    JsonWriter json(/*pretty=*/false);
    json.begin_object();
    json.field("demo", r.demo);
    json.field("plugin", r.plugin);
    json.field("resolution", std::to_string(r.width) + "x" + std::to_string(r.height));
    json.field("width", r.width);
    json.field("height", r.height);
    json.field("gl_renderer", r.gl_renderer);
    json.field("gl_version", r.gl_version);
    write_frame_fields(json, r.frames);
    write_gpu_fields(json, r);
    json.end_object();
    return json.str();
}

std::string append_bench_record(const std::string& path, const BenchRecord& record) {
    std::string line = bench_record_json(record) + "\n";
    std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "ab"));
    if (!file) return path + ": cannot open for appending: " + std::strerror(errno);
    if (std::fwrite(line.data(), 1, line.size(), file.get()) != line.size() ||
        std::fflush(file.get()) != 0) {
        return path + ": write failed: " + std::strerror(errno);
    }
    return {};
}

}  // namespace nq
