// Which world surfaces to draw this frame: Quake's PVS walk plus frustum culling.
//
// Each cull(): find the eye's leaf, decompress its PVS row, mark the visible leafs and their
// ancestor nodes, then walk the node tree from the root, front to back, skipping unmarked nodes
// and nodes/leafs whose boxes lie outside the frustum; every surface listed by a visited leaf
// is visible. The list comes out grouped by texture, the groups ordered by their nearest surface
// and front to back within a group, so a renderer drawing it in order draws roughly front to
// back.
//
// Without vis data, or with the eye in solid or outside the map (leaf 0), every world leaf
// counts as potentially visible, as in Quake; the frustum still culls. Surfaces are not culled
// by facing: plugins that draw outlines need back faces too.
//
// Steady state allocates nothing: all scratch space is sized at construction, and marks are
// frame numbers compared with the current one instead of arrays cleared every frame.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "formats/bsp.h"
#include "render/frustum.h"

namespace nq {

class WorldCuller {
  public:
    // Keeps a reference to `bsp`, which must outlive the culler.
    explicit WorldCuller(const Bsp& bsp);

    // Capacity the output of cull() needs: the world model's surface count.
    size_t max_visible_surfaces() const { return world_face_count_; }

    // Writes the visible surface indices (= BSP face indices, = nqr_brush_model surface indices)
    // to `out` and returns how many. If `out` is shorter than max_visible_surfaces(), the list
    // is cut to fit.
    uint32_t cull(const glm::vec3& eye, const Frustum& frustum, std::span<uint32_t> out);

    // Results of the last cull():
    uint32_t eye_leaf() const { return eye_leaf_; }
    // Whether the PVS marked `leaf` (frustum not applied).
    bool leaf_potentially_visible(uint32_t leaf) const;
    // Whether any leaf the box touches is potentially visible, for culling entities as Quake
    // culls them by the leafs they stand in. Boxes in solid only or outside the map: false.
    bool box_potentially_visible(const glm::vec3& mins, const glm::vec3& maxs) const;
    // Leafs marked by the PVS and leafs that also passed the frustum.
    uint32_t pvs_leaf_count() const { return pvs_leafs_; }
    uint32_t drawn_leaf_count() const { return drawn_leafs_; }

  private:
    static constexpr int32_t kNoParent = -1;
    static constexpr uint32_t kUnranked = ~0u;

    void build_parents(int32_t node, int32_t parent, int depth);
    void next_frame();
    void mark_all_leafs();
    void mark_pvs_leafs(uint32_t leaf);
    void mark_leaf(uint32_t leaf);
    void walk(int32_t node, const glm::vec3& eye, const Frustum& frustum, int depth);
    void visit_leaf(uint32_t leaf, const Frustum& frustum);
    uint32_t group_by_texture(std::span<uint32_t> out);
    bool box_touches_visible(int32_t node, const glm::vec3& mins, const glm::vec3& maxs,
                             int depth) const;

    const Bsp& bsp_;
    uint32_t world_first_face_ = 0;
    uint32_t world_face_count_ = 0;
    uint32_t world_leafs_ = 0;            // leafs 1..world_leafs_ have PVS bits
    std::vector<int32_t> node_parent_;    // per node: parent node or kNoParent
    std::vector<int32_t> leaf_parent_;    // per leaf
    std::vector<uint32_t> face_texture_;  // per face: sort bucket

    uint32_t frame_ = 0;        // 0 = no cull() yet
    bool all_visible_ = false;  // no PVS this frame: every world leaf counts
    std::vector<uint32_t> node_mark_, leaf_mark_, face_mark_;
    std::vector<uint8_t> pvs_row_;
    std::vector<uint32_t> scratch_;  // visible faces in walk order
    uint32_t scratch_count_ = 0;
    std::vector<uint32_t> bucket_start_;  // per rank
    std::vector<uint32_t> bucket_rank_;   // per texture: its rank this frame, kUnranked none
    uint32_t eye_leaf_ = 0;
    uint32_t pvs_leafs_ = 0;
    uint32_t drawn_leafs_ = 0;
};

}  // namespace nq
