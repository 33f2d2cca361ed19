#include "video/frame_trace.h"

#include <cstdio>

#include "common/file_io.h"

namespace nq {
namespace {

constexpr std::array<std::string_view, kTraceStages> kStageNames = {
    "frame_start", "input",     "demo",       "scene", "world",   "brush", "alias",
    "sprites",     "particles", "obscurance", "post",  "overlay", "swap",  "sound"};

// Rows whose GPU results may still arrive: the timers read a frame back this many frames late.
constexpr size_t kGpuSearchDepth = kGpuTimerFramesInFlight + 4;

void append_number(std::string& text, double value) {
    char buffer[32];
    const int n = std::snprintf(buffer, sizeof buffer, "\t%.3f", value);
    text.append(buffer, static_cast<size_t>(n));
}

}  // namespace

std::string_view trace_stage_name(TraceStage stage) {
    return kStageNames[static_cast<size_t>(stage)];
}

void FrameTrace::enable(size_t capacity) {
    rows_.assign(std::max<size_t>(capacity, 1), Row{});
    clear();
}

void FrameTrace::clear() {
    count_ = dropped_ = 0;
    in_frame_ = false;
}

void FrameTrace::begin_frame() {
    if (!enabled()) return;
    current_ = Row{};
    in_frame_ = true;
    last_lap_ = Clock::now();
}

void FrameTrace::lap(TraceStage stage) {
    if (!in_frame_) return;
    const Clock::time_point now = Clock::now();
    current_.stage_ms[static_cast<size_t>(stage)] +=
        std::chrono::duration<float, std::milli>(now - last_lap_).count();
    last_lap_ = now;
}

void FrameTrace::set_gpu_frame(uint64_t gpu_serial) {
    current_.gpu_serial = gpu_serial;
    current_.has_gpu_serial = in_frame_;
}

void FrameTrace::set_contents(const FrameContents& contents) {
    if (in_frame_) current_.contents = contents;
}

void FrameTrace::end_frame(bool keep) {
    if (!in_frame_) return;
    in_frame_ = false;
    if (!keep) return;
    if (count_ == rows_.size()) {
        ++dropped_;
        return;
    }
    rows_[count_++] = current_;
}

void FrameTrace::gpu_frame_timed(uint64_t frame, std::span<const uint64_t> pass_nanoseconds) {
    const size_t oldest = count_ > kGpuSearchDepth ? count_ - kGpuSearchDepth : 0;
    for (size_t i = count_; i-- > oldest;) {
        Row& row = rows_[i];
        if (!row.has_gpu_serial || row.gpu_serial != frame) continue;
        for (size_t pass = 0; pass < pass_nanoseconds.size() && pass < row.gpu_ms.size(); ++pass) {
            row.gpu_ms[pass] =
                static_cast<float>(static_cast<double>(pass_nanoseconds[pass]) / 1e6);
        }
        row.gpu_timed = true;
        return;
    }
}

std::string FrameTrace::append_to(const std::string& path, const TraceHeader& header,
                                  const GpuPassTimers* timers) const {
    const size_t first = count_ > 0 ? 1 : 0;
    const int gpu_passes = timers && timers->active() ? timers->num_passes() : 0;
    std::string text = "# ";
    text.append(header.demo).append(" ").append(header.plugin).append(" ");
    text.append(std::to_string(header.width)).append("x").append(std::to_string(header.height));
    text.append(" ").append(std::to_string(count_ - first)).append("\n");
    if (dropped_ > 0) text += "# trace full: " + std::to_string(dropped_) + " frames left out\n";
    text += "frame\ttotal_ms";
    for (std::string_view name : kStageNames) text.append("\t").append(name).append("_ms");
    for (int pass = 0; pass < gpu_passes; ++pass) {
        text.append("\tgpu_").append(timers->pass_name(pass)).append("_ms");
    }
    text += "\tentities\tdlights\tparticles\n";
    for (size_t i = first; i < count_; ++i) {
        const Row& row = rows_[i];
        text += std::to_string(i - first);
        double total = 0;
        for (float ms : row.stage_ms) total += ms;
        append_number(text, total);
        for (float ms : row.stage_ms) append_number(text, ms);
        for (int pass = 0; pass < gpu_passes; ++pass) {
            if (row.gpu_timed) {
                append_number(text, row.gpu_ms[static_cast<size_t>(pass)]);
            } else {
                text += "\t";  // results never read (the last frames of the run)
            }
        }
        for (uint32_t count :
             {row.contents.entities, row.contents.dlights, row.contents.particles}) {
            text.append("\t").append(std::to_string(count));
        }
        text.append("\n");
    }
    return append_file(path, text);
}

}  // namespace nq
