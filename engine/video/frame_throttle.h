// Bounds how far the engine runs ahead of the GL driver, as a real swap chain does.
//
// Why a bound: Mesa llvmpipe drawing into an offscreen pbuffer (headless runs, benchmarks)
// never makes a swap wait, so the engine queued frame after frame and the driver drained the
// queue at the next call that had to wait for it (reading back a GPU timer, updating a texture
// the queued frames still read): one frame then took the time of many.
//
// Why the wait comes before the swap: the CPU builds frame N while the driver draws frame
// N-1, and frame N is handed over (swapped, flushed) only once N-1 is finished. Waiting after
// the swap instead (for N-2, with N-1 and N queued) had a software rasteriser's threads start
// on the next queued frame the moment the awaited one finished; holding every core, they kept
// the engine's woken thread off the CPU for a scheduler slice (~1-4 ms), so a slow frame was
// followed by an almost free one: play_lq1m1's 99th-percentile frame was ~0.2-0.3x the median
// longer for it (docs/benchmarks.md, "Removed: frames bunched by the wait for the rasteriser"). With nothing
// queued behind the awaited frame, the rasteriser goes idle and the engine resumes at once.
// On a GPU the driver has been consuming frame N's commands as they came, so the wait costs
// no GPU time.
//
// No allocation; one fence held between frames, four GL calls per frame.
#pragma once

#include <epoxy/gl.h>

#include <cstdint>

namespace nq {

class FrameThrottle {
  public:
    // A driver that has not finished a frame in this long is hung or lost: carry on.
    static constexpr uint64_t kWaitLimitNanoseconds = 2'000'000'000;

    FrameThrottle() = default;
    ~FrameThrottle() { release(); }
    FrameThrottle(const FrameThrottle&) = delete;
    FrameThrottle& operator=(const FrameThrottle&) = delete;

    // Call with a frame's commands issued, just before its swap: waits until the frame
    // submitted before it is finished. Does not flush, so the driver is not handed this
    // frame's commands early.
    void before_swap();
    // Call right after the swap: fences the frame and flushes it to the driver.
    void after_swap();
    // Deletes the fence still held; a no-op without a current context (it took it along).
    void release();

  private:
    GLsync previous_frame_ = nullptr;
};

}  // namespace nq
