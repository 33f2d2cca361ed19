#include "video/frame_throttle.h"

#include "video/gl_context_setup.h"

namespace nq {

void FrameThrottle::before_swap() {
    if (!previous_frame_) return;
    // No GL_SYNC_FLUSH_COMMANDS_BIT: after_swap() flushed that fence, and flushing now would
    // queue this frame's commands behind it (the contention the wait is there to avoid).
    glClientWaitSync(previous_frame_, 0, kWaitLimitNanoseconds);
    glDeleteSync(previous_frame_);
    previous_frame_ = nullptr;
}

void FrameThrottle::after_swap() {
    if (previous_frame_) glDeleteSync(previous_frame_);  // before_swap() was not called
    previous_frame_ = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    glFlush();
}

void FrameThrottle::release() {
    if (previous_frame_ && gl_context_is_current()) glDeleteSync(previous_frame_);
    previous_frame_ = nullptr;
}

}  // namespace nq
