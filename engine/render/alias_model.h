// An alias model (MDL) as the renderer ABI's nqr_alias_model: every pose decoded into one
// array in frame order, frames and skins with their intervals. Owns the Mdl and the arrays.
#pragma once

#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "formats/mdl.h"
#include "nqr_renderer.h"

namespace nq {

// Quake's default time a frame or skin is shown when the file gives none (single frames and
// single skins): 0.1 s. Their intervals arrays hold just this value, so a renderer can treat
// every frame and skin as a group.
inline constexpr float kDefaultAnimationInterval = 0.1f;

class AliasModelData {
  public:
    static std::shared_ptr<const AliasModelData> build(Mdl mdl);

    AliasModelData(const AliasModelData&) = delete;
    AliasModelData& operator=(const AliasModelData&) = delete;

    const nqr_alias_model& abi() const { return alias_; }
    const Mdl& mdl() const { return mdl_; }
    // Bounds of every decoded vertex of every pose, in model space (not the stored per-frame
    // boxes, which tools write loosely), and the largest distance of a vertex from the origin.
    const glm::vec3& mins() const { return mins_; }
    const glm::vec3& maxs() const { return maxs_; }
    float radius() const { return radius_; }
    // Bounds of one pose's decoded vertices in model space (poses numbered as in the ABI's
    // nqr_alias_frame::first_pose); the whole model's for a pose that does not exist.
    struct PoseBounds {
        glm::vec3 mins{0.0f}, maxs{0.0f};
    };
    PoseBounds pose_bounds(uint32_t pose) const;

  private:
    AliasModelData() = default;
    void convert_geometry();
    void convert_frames();
    void convert_skins();
    void compute_bounds();
    void link_abi();

    Mdl mdl_;
    std::vector<int32_t> st_;
    std::vector<int32_t> triangles_;
    std::vector<nqr_alias_vertex> poses_;
    std::vector<std::vector<float>> frame_intervals_;
    std::vector<nqr_alias_frame> frames_;
    std::vector<std::vector<const uint8_t*>> skin_images_;
    std::vector<std::vector<float>> skin_intervals_;
    std::vector<nqr_alias_skin> skins_;
    std::vector<PoseBounds> pose_bounds_;
    glm::vec3 mins_{0.0f}, maxs_{0.0f};
    float radius_ = 0.0f;
    nqr_alias_model alias_{};
};

}  // namespace nq
