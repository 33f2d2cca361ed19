#include "render/world_culler.h"

#include <algorithm>

namespace nq {

namespace {

float plane_distance(const BspPlane& plane, const glm::vec3& p) {
    return plane.normal[0] * p.x + plane.normal[1] * p.y + plane.normal[2] * p.z - plane.dist;
}

glm::vec3 to_vec3(const BspVec3& v) {
    return {v[0], v[1], v[2]};
}

// Quake's PVS row coding: a non-zero byte stands for itself, a 0 byte is followed by the
// number of zero bytes it stands for. `row` must be zero-filled; decoding stops at the end of
// the data or of the row.
void decode_pvs_row(std::span<const uint8_t> data, size_t offset, std::span<uint8_t> row) {
    size_t in = offset, produced = 0;
    while (produced < row.size() && in < data.size()) {
        const uint8_t byte = data[in++];
        if (byte != 0) {
            row[produced++] = byte;
        } else if (in < data.size()) {
            produced += std::min<size_t>(data[in++], row.size() - produced);
        }
    }
}

}  // namespace

WorldCuller::WorldCuller(const Bsp& bsp) : bsp_(bsp) {
    node_parent_.assign(bsp.nodes.size(), kNoParent);
    leaf_parent_.assign(bsp.leafs.size(), kNoParent);
    node_mark_.assign(bsp.nodes.size(), 0);
    leaf_mark_.assign(bsp.leafs.size(), 0);
    face_mark_.assign(bsp.faces.size(), 0);
    pvs_row_.assign(pvs_row_bytes(bsp), 0);
    bucket_start_.assign(bsp.textures.size() + 2, 0);
    bucket_rank_.assign(bsp.textures.size() + 1, kUnranked);
    face_texture_.resize(bsp.faces.size());
    const auto no_texture = static_cast<uint32_t>(bsp.textures.size());
    for (size_t f = 0; f < bsp.faces.size(); ++f) {
        const uint32_t miptex = bsp.texinfo[bsp.faces[f].texinfo].miptex;
        face_texture_[f] = miptex < bsp.textures.size() ? miptex : no_texture;
    }
    if (bsp.models.empty()) return;
    const BspModel& world = bsp.models[0];
    world_first_face_ = std::min<uint32_t>(world.first_face, uint32_t(bsp.faces.size()));
    world_face_count_ =
        std::min<uint32_t>(world.num_faces, uint32_t(bsp.faces.size()) - world_first_face_);
    world_leafs_ = std::min<uint32_t>(world.visleafs, uint32_t(bsp.leafs.size() - 1));
    scratch_.assign(world_face_count_, 0);
    build_parents(world.headnodes[0], kNoParent, 0);
}

// Records one parent per node and leaf reachable from the world's root. Subtrees reached a
// second time (tools may share them) keep their first parent: marking that one path is enough
// for the walk to reach them.
void WorldCuller::build_parents(int32_t node, int32_t parent, int depth) {
    if (depth > kBspMaxTreeDepth) return;
    if (node < 0) {
        const auto leaf = static_cast<uint32_t>(-(node + 1));
        if (leaf != 0 && leaf < leaf_parent_.size() && leaf_parent_[leaf] == kNoParent) {
            leaf_parent_[leaf] = parent;
        }
        return;
    }
    if (static_cast<size_t>(node) >= bsp_.nodes.size()) return;
    if (node_parent_[node] != kNoParent) return;               // seen before
    node_parent_[node] = parent == kNoParent ? node : parent;  // the root is its own parent
    for (int32_t child : bsp_.nodes[node].children) build_parents(child, node, depth + 1);
}

void WorldCuller::next_frame() {
    if (++frame_ == 0) {  // wrapped after 2^32 frames: old marks could look current
        std::fill(node_mark_.begin(), node_mark_.end(), 0);
        std::fill(leaf_mark_.begin(), leaf_mark_.end(), 0);
        std::fill(face_mark_.begin(), face_mark_.end(), 0);
        frame_ = 1;
    }
    scratch_count_ = 0;
    pvs_leafs_ = drawn_leafs_ = 0;
    all_visible_ = false;
}

void WorldCuller::mark_leaf(uint32_t leaf) {
    if (leaf == 0 || leaf >= leaf_mark_.size()) return;
    leaf_mark_[leaf] = frame_;
    ++pvs_leafs_;
    for (int32_t node = leaf_parent_[leaf]; node != kNoParent && node_mark_[node] != frame_;) {
        node_mark_[node] = frame_;
        const int32_t up = node_parent_[node];
        node = up == node ? kNoParent : up;  // stop at the root
    }
}

void WorldCuller::mark_all_leafs() {
    all_visible_ = true;
    pvs_leafs_ = world_leafs_;
}

void WorldCuller::mark_pvs_leafs(uint32_t leaf) {
    std::fill(pvs_row_.begin(), pvs_row_.end(), 0);
    decode_pvs_row(bsp_.visibility, static_cast<size_t>(bsp_.leafs[leaf].vis_offset), pvs_row_);
    for (uint32_t i = 0; i < world_leafs_; ++i) {
        if (pvs_row_[i >> 3] & (1u << (i & 7))) mark_leaf(i + 1);
    }
}

uint32_t WorldCuller::cull(const glm::vec3& eye, const Frustum& frustum, std::span<uint32_t> out) {
    next_frame();
    if (bsp_.models.empty() || bsp_.leafs.empty()) return 0;
    eye_leaf_ = leaf_at(bsp_, {eye.x, eye.y, eye.z});
    const BspLeaf& leaf = bsp_.leafs[eye_leaf_];
    const bool no_pvs = eye_leaf_ == 0 || leaf.contents == bsp_contents::solid ||
                        leaf.vis_offset < 0 || bsp_.visibility.empty();
    if (no_pvs) {
        mark_all_leafs();
    } else {
        mark_pvs_leafs(eye_leaf_);
    }
    walk(bsp_.models[0].headnodes[0], eye, frustum, 0);
    return group_by_texture(out);
}

void WorldCuller::walk(int32_t node, const glm::vec3& eye, const Frustum& frustum, int depth) {
    if (depth > kBspMaxTreeDepth) return;
    if (node < 0) {
        visit_leaf(static_cast<uint32_t>(-(node + 1)), frustum);
        return;
    }
    if (static_cast<size_t>(node) >= bsp_.nodes.size()) return;
    if (!all_visible_ && node_mark_[node] != frame_) return;
    const BspNode& n = bsp_.nodes[node];
    if (frustum.box_outside(to_vec3(n.mins), to_vec3(n.maxs))) return;
    // Near side first, so each texture's surfaces come out roughly front to back.
    const int near = plane_distance(bsp_.planes[n.plane], eye) >= 0 ? 0 : 1;
    walk(n.children[near], eye, frustum, depth + 1);
    walk(n.children[near ^ 1], eye, frustum, depth + 1);
}

void WorldCuller::visit_leaf(uint32_t leaf, const Frustum& frustum) {
    if (leaf == 0 || leaf >= bsp_.leafs.size()) return;
    if (!all_visible_ && leaf_mark_[leaf] != frame_) return;
    const BspLeaf& l = bsp_.leafs[leaf];
    if (frustum.box_outside(to_vec3(l.mins), to_vec3(l.maxs))) return;
    ++drawn_leafs_;
    const uint32_t world_end = world_first_face_ + world_face_count_;
    for (uint32_t i = 0; i < l.num_marksurfaces; ++i) {
        const uint32_t face = bsp_.marksurfaces[l.first_marksurface + i];
        if (face < world_first_face_ || face >= world_end || face_mark_[face] == frame_) continue;
        face_mark_[face] = frame_;
        if (scratch_count_ < scratch_.size()) scratch_[scratch_count_++] = face;
    }
}

// Faces grouped by texture (one draw call each), the groups in the order of their nearest face
// and each group in walk order, so the frame draws roughly front to back and depth testing can
// skip shading what is hidden. A counting sort over the groups' ranks keeps the walk order.
uint32_t WorldCuller::group_by_texture(std::span<uint32_t> out) {
    std::fill(bucket_rank_.begin(), bucket_rank_.end(), kUnranked);
    std::fill(bucket_start_.begin(), bucket_start_.end(), 0);
    uint32_t ranks = 0;
    for (uint32_t i = 0; i < scratch_count_; ++i) {
        uint32_t& rank = bucket_rank_[face_texture_[scratch_[i]]];
        if (rank == kUnranked) rank = ranks++;
        ++bucket_start_[rank + 1];
    }
    for (uint32_t b = 1; b <= ranks; ++b) bucket_start_[b] += bucket_start_[b - 1];
    for (uint32_t i = 0; i < scratch_count_; ++i) {
        const uint32_t face = scratch_[i];
        const uint32_t at = bucket_start_[bucket_rank_[face_texture_[face]]]++;
        if (at < out.size()) out[at] = face;
    }
    return static_cast<uint32_t>(std::min<size_t>(scratch_count_, out.size()));
}

bool WorldCuller::leaf_potentially_visible(uint32_t leaf) const {
    if (frame_ == 0 || leaf == 0 || leaf >= bsp_.leafs.size()) return false;
    if (all_visible_) return leaf_parent_[leaf] != kNoParent;
    return leaf_mark_[leaf] == frame_;
}

bool WorldCuller::box_potentially_visible(const glm::vec3& mins, const glm::vec3& maxs) const {
    if (frame_ == 0 || bsp_.models.empty()) return false;
    return box_touches_visible(bsp_.models[0].headnodes[0], mins, maxs, 0);
}

bool WorldCuller::box_touches_visible(int32_t node, const glm::vec3& mins, const glm::vec3& maxs,
                                      int depth) const {
    if (depth > kBspMaxTreeDepth) return false;
    if (node < 0) return leaf_potentially_visible(static_cast<uint32_t>(-(node + 1)));
    if (static_cast<size_t>(node) >= bsp_.nodes.size()) return false;
    const BspNode& n = bsp_.nodes[node];
    const BspPlane& plane = bsp_.planes[n.plane];
    // Distances of the box corners nearest and farthest along the plane normal.
    float lo = -plane.dist, hi = -plane.dist;
    for (int i = 0; i < 3; ++i) {
        const float a = plane.normal[i] * mins[i], b = plane.normal[i] * maxs[i];
        lo += std::min(a, b);
        hi += std::max(a, b);
    }
    if (hi >= 0 && box_touches_visible(n.children[0], mins, maxs, depth + 1)) return true;
    return lo < 0 && box_touches_visible(n.children[1], mins, maxs, depth + 1);
}

}  // namespace nq
