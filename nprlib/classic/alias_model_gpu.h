// GPU side of an alias model: the mesh (pose-vertex index + skin coordinates), all poses in one
// buffer texture (blended in the vertex shader), and every skin image as a lit base texture with
// its fullbright mask. Holey models (MDL flag 0x4000, a QuakeSpasm extension) cut index 255 out.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "gl/handles.h"
#include "nqr_renderer.h"

namespace nq::npr::classic {

inline constexpr uint32_t kAliasFlagHoley = 1u << 14;

struct SkinImageGpu {
    gl::Texture base;
    gl::Texture fullbright;  // empty: no fullbright pixel
};

class AliasModelGpu {
  public:
    static std::unique_ptr<AliasModelGpu> create(gl::ObjectTracker* tracker,
                                                 const nqr_alias_model& model,
                                                 const uint8_t* palette_rgb, std::string& error);

    const nqr_alias_model& model() const { return *model_; }
    GLuint vertex_array() const { return vertex_array_.id(); }
    GLuint pose_texture() const { return pose_texture_.id(); }
    // The pose texture's texels on the CPU (alias_mesh.h's layout), for drawers that blend
    // normals there.
    const std::vector<uint8_t>& pose_texels() const { return pose_texels_; }
    GLsizei index_count() const { return index_count_; }
    bool holey() const { return (model_->flags & kAliasFlagHoley) != 0; }

    // The image to draw for (skin, image), clamped into range; nullptr when there is no skin.
    const SkinImageGpu* skin_image(uint32_t skin, uint32_t image) const;
    // The palette pixels behind it (for player colour translation); nullptr likewise.
    const uint8_t* skin_pixels(uint32_t skin, uint32_t image) const;

  private:
    AliasModelGpu() = default;
    bool upload_poses(gl::ObjectTracker* tracker, const std::vector<uint8_t>& texels,
                      std::string& error);
    void upload_skins(gl::ObjectTracker* tracker, const uint8_t* palette_rgb);
    bool locate(uint32_t& skin, uint32_t& image) const;

    const nqr_alias_model* model_ = nullptr;
    gl::VertexArray vertex_array_;
    gl::Buffer vertices_, indices_, poses_;
    gl::Texture pose_texture_;
    GLsizei index_count_ = 0;
    std::vector<std::vector<SkinImageGpu>> skins_;
    std::vector<uint8_t> pose_texels_;
};

}  // namespace nq::npr::classic
