// A map's faces as occluders: which of them hide what lies behind (opaque, textured, not sky,
// not liquid, not fence), each one's plane pushed back by the distance its vertices stray from
// it, and for every polygon edge the faces of the same model (the world, or one door or
// platform, which moves on its own) that use the same edge the other way round.
//
// Two front-facing faces that share an edge lie on opposite sides of it on screen, so together
// they leave no gap along it: the occlusion rasteriser may fill pixels right up to such an edge.
// An edge without a partner drawn this frame (a silhouette of the world, a T-junction, a face
// met by sky or water) is an outline, and pixels near it are left out.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "nqr_renderer.h"

namespace nq {

struct Bsp;

struct SurfaceRange {
    uint32_t first = 0, count = 0;
};

struct OccluderFace {
    uint32_t first_vertex = 0, num_vertices = 0;  // range in positions / vertex_ids
    glm::vec3 normal{0.0f};
    float dist = 0.0f;  // the face's plane: dot(normal, p) = dist
    // The plane moved back (toward its back side) by the farthest a vertex lies in front of
    // it: every point of the drawn polygon is on or in front of this plane.
    float back_dist = 0.0f;
    bool occludes = false;
};

// The ranges of a BSP's models (the world first), clipped to its face count.
std::vector<SurfaceRange> bsp_model_ranges(const Bsp& bsp);

class OccluderMesh {
  public:
    OccluderMesh() = default;
    // The surfaces of `brush` in `models` (the map's own model and its inline submodels; a
    // surface in none of them occludes nothing). `brush` must outlive the mesh: positions are
    // read from it.
    OccluderMesh(const nqr_brush_model& brush, std::span<const SurfaceRange> models);

    // Indexed by surface index (= BSP face index); faces outside the model's range occlude
    // nothing.
    std::span<const OccluderFace> faces() const { return faces_; }
    glm::vec3 position(uint32_t vertex) const;
    uint32_t vertex_id(uint32_t vertex) const { return vertex_ids_[vertex]; }
    // Faces walking the edge from polygon vertex `vertex` to the next one the other way round.
    std::span<const uint32_t> partners(uint32_t vertex) const;
    uint32_t max_polygon_vertices() const { return max_polygon_vertices_; }

  private:
    void link_partners();

    const float* positions_ = nullptr;
    const uint32_t* vertex_ids_ = nullptr;
    std::vector<OccluderFace> faces_;
    std::vector<uint32_t> vertex_face_;    // per polygon vertex: its face
    std::vector<uint32_t> face_model_;     // per face: index into the models given
    std::vector<uint32_t> partner_start_;  // per polygon vertex + 1: range in partners_
    std::vector<uint32_t> partners_;
    uint32_t max_polygon_vertices_ = 0;
};

}  // namespace nq
