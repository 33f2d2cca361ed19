#include "client/animation.h"

#include <algorithm>
#include <cmath>

namespace nq {
namespace {

const AnimationGroup* group_or_first(const std::vector<AnimationGroup>& groups, int index) {
    if (groups.empty()) return nullptr;
    if (index < 0 || static_cast<size_t>(index) >= groups.size()) return &groups[0];
    return &groups[static_cast<size_t>(index)];
}

float clamp01(double v) {
    return static_cast<float>(std::clamp(v, 0.0, 1.0));
}

}  // namespace

GroupPose resolve_group_pose(const AnimationGroup& group, double time) {
    GroupPose out{group.first, group.first, 1.0f};
    if (group.count <= 1 || group.intervals.size() != group.count) return out;
    const double cycle = group.intervals.back();
    if (!(cycle > 0)) return out;
    double t = std::fmod(time, cycle);
    if (t < 0) t += cycle;
    uint32_t k = 0;
    while (k + 1 < group.count && group.intervals[k] <= t) ++k;
    const double start = k == 0 ? 0.0 : group.intervals[k - 1];
    const double duration = group.intervals[k] - start;
    out.index = group.first + k;
    out.previous = group.first + (k + group.count - 1) % group.count;
    out.phase = duration > 0 ? clamp01((t - start) / duration) : 1.0f;
    return out;
}

PoseBlend resolve_frame_blend(const ModelInfo& model, const FrameLerp& lerp, double time) {
    const AnimationGroup* current = group_or_first(model.frames, lerp.frame);
    if (!current) return {};
    const GroupPose now = resolve_group_pose(*current, time + lerp.syncbase);
    if (!model.lerp_poses) return {now.index, now.index, 1.0f};

    const double since = time - lerp.frame_start;
    if (lerp.previous_frame != lerp.frame && since < lerp.interval) {
        if (!(lerp.interval > 0)) return {now.index, now.index, 1.0f};
        const AnimationGroup* before = group_or_first(model.frames, lerp.previous_frame);
        const GroupPose then = resolve_group_pose(*before, lerp.frame_start + lerp.syncbase);
        return {then.index, now.index, clamp01(since / lerp.interval)};
    }
    if (current->count > 1) return {now.previous, now.index, now.phase};
    return {now.index, now.index, 1.0f};
}

uint32_t resolve_skin_image(const ModelInfo& model, int skin, double time) {
    const AnimationGroup* group = group_or_first(model.skins, skin);
    if (!group) return 0;
    return resolve_group_pose(*group, time).index - group->first;
}

}  // namespace nq
