#include "video/frame_throttle.h"

#include "video/gl_context_setup.h"

namespace nq {

void FrameThrottle::frame_submitted() {
    fences_[next_] = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    next_ = (next_ + 1) % fences_.size();
    GLsync oldest = fences_[next_];
    if (!oldest) return;  // fewer frames than the limit so far
    glClientWaitSync(oldest, GL_SYNC_FLUSH_COMMANDS_BIT, kWaitLimitNanoseconds);
    glDeleteSync(oldest);
    fences_[next_] = nullptr;
}

void FrameThrottle::release() {
    const bool current = gl_context_is_current();
    for (GLsync& fence : fences_) {
        if (fence && current) glDeleteSync(fence);
        fence = nullptr;
    }
    next_ = 0;
}

}  // namespace nq
