// What the client needs to know about a loaded model to animate and decorate its entities:
// kind, MDL flags (trails, rotation), sync type, and the pose/image layout of frames and skins.
// The engine builds one per model index after loading the models of a map (from nq::Mdl and
// nq::Spr with the functions below) and hands the table to ClientState::set_model_info.
#pragma once

#include <cstdint>
#include <vector>

#include "formats/mdl.h"
#include "formats/spr.h"

namespace nq {

enum class ModelKind : uint8_t { None, Brush, Alias, Sprite };

// A frame (or skin): one pose, or a group of poses cycling with cumulative end times.
// Poses (images) are numbered across the whole model, as nqr_alias_frame::first_pose does.
struct AnimationGroup {
    uint32_t first = 0;
    uint32_t count = 1;
    std::vector<float> intervals;  // count cumulative end times when count > 1, else empty
};

struct ModelInfo {
    ModelKind kind = ModelKind::None;
    int32_t flags = 0;        // MDL flags (kEfRocket, kEfRotate, ...); 0 for brushes and sprites
    int32_t sync_type = 0;    // 1: each entity gets a random animation phase
    bool lerp_poses = false;  // alias models blend poses; sprites show one image at a time
    std::vector<AnimationGroup> frames;
    std::vector<AnimationGroup> skins;  // alias only; images numbered within the skin
};

ModelInfo model_info_from_mdl(const Mdl& mdl);
ModelInfo model_info_from_spr(const Spr& spr);
ModelInfo brush_model_info();

}  // namespace nq
