#include "client/client_entity.h"

#include <algorithm>

namespace nq {

void track_frame(AnimationTracker& tracker, int frame, double time, double lerp_finish) {
    FrameLerp& lerp = tracker.lerp;
    if (tracker.reset) {
        lerp.frame = lerp.previous_frame = frame;
        lerp.frame_start = time;
        lerp.interval = kDefaultFrameInterval;
        tracker.reset = false;
        return;
    }
    if (frame == lerp.frame) return;
    lerp.previous_frame = tracker.reset_next_change ? frame : lerp.frame;
    tracker.reset_next_change = false;
    lerp.frame = frame;
    lerp.frame_start = time;
    // A finish time already past leaves no time to blend: snap (interval 0).
    lerp.interval = lerp_finish >= 0 ? std::max(0.0, lerp_finish - time) : kDefaultFrameInterval;
}

}  // namespace nq
