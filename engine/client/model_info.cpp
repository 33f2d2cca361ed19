#include "client/model_info.h"

namespace nq {
namespace {

AnimationGroup make_group(uint32_t first, size_t count, const std::vector<float>& intervals) {
    AnimationGroup g;
    g.first = first;
    g.count = static_cast<uint32_t>(count);
    if (count > 1 && intervals.size() == count) g.intervals = intervals;
    return g;
}

}  // namespace

ModelInfo model_info_from_mdl(const Mdl& mdl) {
    ModelInfo info;
    info.kind = ModelKind::Alias;
    info.flags = mdl.header.flags;
    info.sync_type = mdl.header.sync_type;
    info.lerp_poses = true;
    uint32_t pose = 0;
    for (const MdlFrame& frame : mdl.frames) {
        info.frames.push_back(make_group(pose, frame.poses.size(), frame.intervals));
        pose += static_cast<uint32_t>(frame.poses.size());
    }
    for (const MdlSkin& skin : mdl.skins) {
        // Skin images are numbered within their skin (nqr_entity::skin_image).
        info.skins.push_back(make_group(0, skin.images.size(), skin.intervals));
    }
    return info;
}

ModelInfo model_info_from_spr(const Spr& spr) {
    ModelInfo info;
    info.kind = ModelKind::Sprite;
    info.sync_type = spr.header.sync_type;
    uint32_t image = 0;
    for (const SprFrame& frame : spr.frames) {
        info.frames.push_back(make_group(image, frame.pictures.size(), frame.intervals));
        image += static_cast<uint32_t>(frame.pictures.size());
    }
    return info;
}

ModelInfo brush_model_info() {
    ModelInfo info;
    info.kind = ModelKind::Brush;
    return info;
}

}  // namespace nq
