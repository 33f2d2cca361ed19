#include "classic/texture_animation.h"

#include <cmath>

#include "abi/abi_access.h"

namespace nq::npr::classic {
namespace {

constexpr uint32_t kMaxChain = 10;

int32_t frame_of_chain(const int32_t* chain, uint32_t length, double time) {
    if (length == 0 || length > kMaxChain) return -1;
    const double step = std::floor(time * kTextureFramesPerSecond);
    const double index = std::fmod(step, static_cast<double>(length));
    return chain[static_cast<uint32_t>(index < 0 ? index + length : index)];
}

}  // namespace

int32_t animated_texture(const nqr_brush_model& brush, int32_t texture, double time,
                         bool alternate) {
    if (texture < 0 || static_cast<uint32_t>(texture) >= brush.num_textures) return texture;
    const nqr_texture& base = abi_element(brush.textures, static_cast<uint32_t>(texture));
    int32_t resolved = -1;
    if (alternate && base.num_alt_anim_frames > 0) {
        resolved = frame_of_chain(base.alt_anim_frames, base.num_alt_anim_frames, time);
    } else {
        resolved = frame_of_chain(base.anim_frames, base.num_anim_frames, time);
    }
    if (resolved < 0 || static_cast<uint32_t>(resolved) >= brush.num_textures) return texture;
    return resolved;
}

}  // namespace nq::npr::classic
