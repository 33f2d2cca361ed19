// Animation resolution: which pose (alias) or image (sprite) an entity shows at a given time,
// and how to blend from the previous one, as FitzQuake-family renderers interpolate:
//  - a frame change blends from the previous frame's pose to the new one over the frame's
//    interval (0.1 s, the usual think time, or the server's U_LERPFINISH time);
//  - a frame group cycles through its poses by its cumulative intervals, each pose blending
//    from the one before it;
//  - skin groups pick their image by time the same way (never blended).
#pragma once

#include <cstdint>

#include "client/model_info.h"

namespace nq {

inline constexpr double kDefaultFrameInterval = 0.1;

// What the renderer draws: pose0 * (1 - lerp) + pose1 * lerp (poses numbered across the model).
struct PoseBlend {
    uint32_t pose0 = 0;
    uint32_t pose1 = 0;
    float lerp = 1;
    bool operator==(const PoseBlend&) const = default;
};

// Where a group's cycle stands at a time.
struct GroupPose {
    uint32_t index = 0;     // pose showing now (group.first + k)
    uint32_t previous = 0;  // the pose before it in the cycle
    float phase = 1;        // 0..1 through the current pose's interval (1 for single poses)
};
GroupPose resolve_group_pose(const AnimationGroup& group, double time);

// An entity's animation memory, kept by the client.
struct FrameLerp {
    int frame = 0;                            // the frame shown now
    int previous_frame = 0;                   // the frame it replaced
    double frame_start = -1e9;                // client time of the change (far past: no blend)
    double interval = kDefaultFrameInterval;  // how long the blend from previous_frame lasts
    float syncbase = 0;                       // random phase for sync_type 1 models
};

// The blend to draw at client time `time`. Frame numbers outside the model show frame 0, as
// Quake does; models without frames (brushes, unknown models) give pose 0.
PoseBlend resolve_frame_blend(const ModelInfo& model, const FrameLerp& lerp, double time);

// The image within skin `skin` to show at `time` (0 for a single image or an unknown skin).
uint32_t resolve_skin_image(const ModelInfo& model, int skin, double time);

}  // namespace nq
