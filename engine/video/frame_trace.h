// The -benchtrace file: per timedemo frame, where the time went, so a slow frame can be
// explained and not only counted. The CPU time of each engine stage (a "lap" clock: each lap()
// charges the time since the previous one to a stage, so the stages add up to the frame), the
// GPU time of each timed pass (GpuPassTimers reports a frame's passes a few frames later), and
// what the frame held (entities, dynamic lights, particles).
//
// Rows are allocated once when tracing is enabled; recording never allocates, and a full
// trace stops recording (the file says how many frames were left out).
//
// File format, appended per timedemo: a line "# <demo> <plugin> <W>x<H> <frames>", a line of
// tab-separated column names, then one tab-separated row per counted frame (the timedemo's
// first frame, which it does not count, left out), times in milliseconds.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "video/gpu_pass_timers.h"

namespace nq {

enum class TraceStage : uint8_t {
    FrameStart,  // clearing the screen, starting the GPU timers
    Input,       // window events, console commands
    Demo,        // reading the demo, or running the game's server and client
    Scene,       // the view, culling and the frame's scene for the plugin
    World,       // the plugin's passes (its begin_frame counts with the world)...
    Brush,
    Alias,
    Sprites,
    Particles,
    Obscurance,
    Post,     // ...its post-process and end_frame
    Overlay,  // view blends, status bar, menu, console, gamma
    Swap,     // presenting the frame
    Sound,    // mixing and spatialising
    Count
};
inline constexpr size_t kTraceStages = static_cast<size_t>(TraceStage::Count);
std::string_view trace_stage_name(TraceStage stage);

struct FrameContents {
    uint32_t entities = 0;
    uint32_t dlights = 0;
    uint32_t particles = 0;
};

struct TraceHeader {
    std::string demo;
    std::string plugin;
    int width = 0;
    int height = 0;
};

class FrameTrace : public GpuFrameListener {
  public:
    static constexpr size_t kDefaultCapacity = size_t{1} << 16;  // 15 minutes at 72 fps

    // Tracing is off (every call a cheap no-op) until enable().
    void enable(size_t capacity = kDefaultCapacity);
    bool enabled() const { return !rows_.empty(); }
    void clear();  // forgets the frames recorded (a new timedemo)

    void begin_frame();
    void lap(TraceStage stage);
    void set_gpu_frame(uint64_t gpu_serial);  // the GPU timers' serial of this frame
    void set_contents(const FrameContents& contents);
    // Keeps the frame's row when `keep` (a frame the timedemo counts).
    void end_frame(bool keep);

    void gpu_frame_timed(uint64_t frame, std::span<const uint64_t> pass_nanoseconds) override;

    size_t frames() const { return count_; }
    size_t dropped() const { return dropped_; }

    // Appends the rows after the first (see the format above); gpu pass names from `timers`
    // (no GPU columns when it is null or inactive). "" on success, else a message.
    std::string append_to(const std::string& path, const TraceHeader& header,
                          const GpuPassTimers* timers) const;

  private:
    using Clock = std::chrono::steady_clock;
    struct Row {
        std::array<float, kTraceStages> stage_ms{};
        std::array<float, kMaxGpuPasses> gpu_ms{};
        FrameContents contents;
        uint64_t gpu_serial = 0;
        bool has_gpu_serial = false;
        bool gpu_timed = false;
    };

    std::vector<Row> rows_;
    size_t count_ = 0;  // rows kept
    size_t dropped_ = 0;
    Row current_;
    bool in_frame_ = false;
    Clock::time_point last_lap_;
};

}  // namespace nq
