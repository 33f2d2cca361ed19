// Bounds how many frames the GL driver may have queued, as a real swap chain does.
//
// Why: Mesa llvmpipe drawing into an offscreen pbuffer (headless runs, benchmarks) never makes
// a swap wait, so the engine queued frame after frame and the driver drained the queue at the
// next call that had to wait for it (reading back a GPU timer, updating a texture the queued
// frames still read): one frame then took the time of many. timedemo counted that as its
// 95th/99th-percentile frame times (2-3x the median) and, without GPU timers, as single frames
// of over a second.
//
// After each swap, frame_submitted() fences the frame and waits until no more than
// kMaxFramesInFlight frames are unfinished. No allocation; two GL calls per frame.
#pragma once

#include <epoxy/gl.h>

#include <array>
#include <cstddef>
#include <cstdint>

namespace nq {

class FrameThrottle {
  public:
    // Two: the CPU prepares the next frame while the driver draws the last two, as a triple
    // buffered swap chain would let it.
    static constexpr size_t kMaxFramesInFlight = 2;
    // A driver that has not finished a frame in this long is hung or lost: carry on.
    static constexpr uint64_t kWaitLimitNanoseconds = 2'000'000'000;

    FrameThrottle() = default;
    ~FrameThrottle() { release(); }
    FrameThrottle(const FrameThrottle&) = delete;
    FrameThrottle& operator=(const FrameThrottle&) = delete;

    // Call right after the swap (with the context current).
    void frame_submitted();
    // Deletes the fences still held; a no-op without a current context (it took them along).
    void release();

  private:
    // One more than the frames allowed in flight: the slot after the newest holds the frame
    // that must be finished before another is started.
    std::array<GLsync, kMaxFramesInFlight + 1> fences_{};
    size_t next_ = 0;
};

}  // namespace nq
