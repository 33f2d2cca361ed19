// GPU geometry of an alias model for the illustrative style: the classic mesh (pose vertex + skin
// coordinates, poses blended from AliasModelGpu's pose texture) with one more attribute, the
// corner's normal slot, so a welded vertex on a crease can carry one normal per smoothing group.
// Every pose's slot normals live in one RGBA8 buffer texture (n * 0.5 + 0.5), blended between
// the entity's two poses like the positions.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "gl/handles.h"
#include "nqr_renderer.h"

namespace nq::npr::illustrative {

// Normals per triangle corner: which slot each corner reads, and every pose's slot normals.
struct CornerNormals {
    uint32_t num_slots = 0;
    std::vector<uint32_t> corner_slots;  // 3 per model triangle, in model.triangles order
    std::vector<glm::vec3> normals;      // normals[pose * num_slots + slot], unit length
};

// The classic normals: one slot per MDL vertex, angle-weighted over its own triangles (no weld,
// no creases). What ill_smooth_normals 0 draws.
CornerNormals mdl_vertex_normals(const nqr_alias_model& model);

class IllustrativeModel {
  public:
    // False (nullptr) with `error` when the normals do not fit the model or the GL's limits.
    static std::unique_ptr<IllustrativeModel> create(gl::ObjectTracker* tracker,
                                                     const nqr_alias_model& model,
                                                     const CornerNormals& normals,
                                                     std::string& error);

    GLuint vertex_array() const { return vertex_array_.id(); }
    GLsizei index_count() const { return index_count_; }
    GLuint normal_texture() const { return normal_texture_.id(); }
    uint32_t normal_slots() const { return normal_slots_; }
    // Model-space height (z) of the lowest and highest vertex over all poses.
    float height_min() const { return height_min_; }
    float height_max() const { return height_max_; }

  private:
    IllustrativeModel() = default;
    bool upload_normals(gl::ObjectTracker* tracker, const CornerNormals& normals,
                        std::string& error);

    gl::VertexArray vertex_array_;
    gl::Buffer vertices_, indices_, normal_buffer_;
    gl::Texture normal_texture_;
    GLsizei index_count_ = 0;
    uint32_t normal_slots_ = 0;
    float height_min_ = 0.0f, height_max_ = 1.0f;
};

}  // namespace nq::npr::illustrative
