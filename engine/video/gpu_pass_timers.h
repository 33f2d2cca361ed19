// GPU time per render pass, measured with GL_TIMESTAMP queries and read back a few frames
// later so the CPU never waits for the GPU.
//
// Passes are named: six built-in ones for the engine's own stages, and up to
// kMaxPluginGpuPasses more named by plugins on first use (the ABI's gpu_pass_begin). Passes are
// begin/end pairs and may nest; time is exclusive: while an inner pass runs, the time counts
// for the inner pass only, so the per-pass totals add up to the GPU time inside all passes.
//
// Every query object and marker array is allocated by init(); begin/end/begin_frame/end_frame
// never allocate. Without timer-query support (or when disabled) every call is a cheap no-op
// and active() is false.
//
// Usage per frame: begin_frame(); { begin(pass); draw; end(); } ...; end_frame(). At the end of a
// run: finish() (waits for the last frames' results), then totals().
#pragma once

#include <epoxy/gl.h>

#include <array>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "video/gpu_pass_totals.h"

namespace nq {

enum class GpuPass : uint8_t { World, Brush, Alias, Sprites, Particles, Post };

inline constexpr int kBuiltinGpuPasses = 6;
inline constexpr int kMaxPluginGpuPasses = 16;
inline constexpr int kMaxGpuPasses = kBuiltinGpuPasses + kMaxPluginGpuPasses;
inline constexpr size_t kMaxGpuPassNameLength = 31;
// Results are read this many frames after they were issued: deep enough that a driver
// queueing two or three frames ahead has finished them.
inline constexpr int kGpuTimerFramesInFlight = 4;
// Begin and end markers per frame (each is one query); passes beyond it go untimed.
inline constexpr int kMaxGpuMarkersPerFrame = 256;
inline constexpr int kMaxGpuPassDepth = 8;

// How the timers were misused or overloaded; all zero in a well-behaved run.
struct GpuTimerDiagnostics {
    uint64_t stalled_reads = 0;   // results not ready after kGpuTimerFramesInFlight frames
    uint64_t dropped_passes = 0;  // marker budget or nesting depth exceeded: pass untimed
    uint64_t unknown_passes = 0;  // name table full or name empty / too long
    uint64_t unbalanced = 0;      // end() without begin(), or passes still open at end_frame()
};

// Told each frame's per-pass times when they are read back (kGpuTimerFramesInFlight frames
// after the frame), for a per-frame trace. `frame` is the frame_serial() the frame had.
class GpuFrameListener {
  public:
    virtual ~GpuFrameListener() = default;
    virtual void gpu_frame_timed(uint64_t frame, std::span<const uint64_t> pass_nanoseconds) = 0;
};

class GpuPassTimers {
  public:
    GpuPassTimers();
    ~GpuPassTimers();  // deletes the queries if a context is still current
    GpuPassTimers(const GpuPassTimers&) = delete;
    GpuPassTimers& operator=(const GpuPassTimers&) = delete;

    // With a GL context current. Returns whether timing is active: false when `enabled` is
    // false or the driver lacks timestamp queries (then everything below does nothing).
    bool init(bool enabled = true);
    void shutdown();
    bool active() const { return active_; }

    void begin_frame();
    void end_frame();  // closes (and reports as unbalanced) passes left open
    void begin(GpuPass pass);
    void begin(std::string_view name);  // built-in or plugin pass name
    void begin(const char* name);       // as the ABI passes it; nullptr counts as unknown
    void end();

    // Waits for every outstanding result: call once at the end of a run, before totals().
    void finish();
    // Zeroes totals, counts and diagnostics and forgets results in flight (between frames).
    void reset();

    // One entry per known pass, built-in ones first, in registration order.
    std::vector<GpuPassTotals> totals() const;
    uint64_t frames_timed() const { return frames_; }
    // The number the frame now being issued has (counted from reset()).
    uint64_t frame_serial() const { return frames_; }
    int num_passes() const { return num_passes_; }
    std::string_view pass_name(int pass) const { return names_[pass].data(); }
    void set_listener(GpuFrameListener* listener) { listener_ = listener; }
    uint64_t total_nanoseconds(std::string_view name) const;
    uint64_t pass_count(std::string_view name) const;
    const GpuTimerDiagnostics& diagnostics() const { return diagnostics_; }

  private:
    struct Marker {
        int8_t pass;
        bool begin;
    };
    struct FrameSlot {
        std::array<GLuint, kMaxGpuMarkersPerFrame> queries{};
        std::array<Marker, kMaxGpuMarkersPerFrame> markers{};
        int count = 0;
        uint64_t serial = 0;
        bool pending = false;  // markers issued, results not read yet
    };

    int find_pass(std::string_view name) const;
    int find_or_add_pass(std::string_view name);
    void begin_index(int pass);
    void add_marker(int pass, bool begin);
    void collect(FrameSlot& slot);
    void attribute(const FrameSlot& slot);

    bool active_ = false;
    bool in_frame_ = false;
    int slot_ = 0;
    std::array<FrameSlot, kGpuTimerFramesInFlight> slots_;
    std::array<GLuint64, kMaxGpuMarkersPerFrame> timestamps_{};  // scratch for collect()

    std::array<std::array<char, kMaxGpuPassNameLength + 1>, kMaxGpuPasses> names_{};
    int num_passes_ = 0;
    std::array<uint64_t, kMaxGpuPasses> nanoseconds_{};
    std::array<uint64_t, kMaxGpuPasses> frame_nanoseconds_{};  // scratch for attribute()
    GpuFrameListener* listener_ = nullptr;
    std::array<uint64_t, kMaxGpuPasses> counts_{};
    uint64_t frames_ = 0;

    // Passes open now: pass index, or -1 for a begin that is not being timed.
    std::array<int8_t, kMaxGpuPassDepth> open_{};
    int depth_ = 0;
    int excess_depth_ = 0;  // begins past kMaxGpuPassDepth, matched by ends that do nothing

    GpuTimerDiagnostics diagnostics_;
};

}  // namespace nq
