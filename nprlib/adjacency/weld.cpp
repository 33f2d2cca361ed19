#include "adjacency/weld.h"

#include <unordered_map>

namespace nq::npr::adjacency {

namespace {

// FNV-1a over the packed coordinates of the poses in [first, last).
uint64_t trajectory_hash(const AliasSource& source, uint32_t vertex, uint32_t first,
                         uint32_t last) {
    uint64_t h = 1469598103934665603ull;
    for (uint32_t pose = first; pose < last; ++pose) {
        for (uint8_t byte : source.packed(pose, vertex)) {
            h = (h ^ byte) * 1099511628211ull;
        }
    }
    return h;
}

bool same_trajectory(const AliasSource& source, uint32_t a, uint32_t b, uint32_t first,
                     uint32_t last) {
    for (uint32_t pose = first; pose < last; ++pose) {
        if (source.packed(pose, a) != source.packed(pose, b)) return false;
    }
    return true;
}

// Vertices whose packed positions agree in every pose of [first, last) share a class.
VertexWeld weld_over_poses(const AliasSource& source, uint32_t first, uint32_t last) {
    VertexWeld weld;
    weld.class_of.resize(source.num_vertices());
    std::unordered_map<uint64_t, std::vector<uint32_t>> classes_by_hash;
    classes_by_hash.reserve(source.num_vertices());
    for (uint32_t v = 0; v < source.num_vertices(); ++v) {
        std::vector<uint32_t>& bucket = classes_by_hash[trajectory_hash(source, v, first, last)];
        uint32_t found = UINT32_MAX;
        for (uint32_t c : bucket) {
            if (same_trajectory(source, weld.representative[c], v, first, last)) {
                found = c;
                break;
            }
        }
        if (found == UINT32_MAX) {
            found = weld.num_classes();
            weld.representative.push_back(v);
            bucket.push_back(found);
        }
        weld.class_of[v] = found;
    }
    return weld;
}

VertexWeld identity_weld(uint32_t num_vertices) {
    VertexWeld weld;
    weld.class_of.resize(num_vertices);
    weld.representative.resize(num_vertices);
    for (uint32_t v = 0; v < num_vertices; ++v) weld.class_of[v] = weld.representative[v] = v;
    return weld;
}

}  // namespace

VertexWeld weld_coincident_vertices(const AliasSource& source) {
    if (source.num_poses() == 0) return identity_weld(source.num_vertices());
    return weld_over_poses(source, 0, source.num_poses());
}

VertexWeld weld_in_one_pose(const AliasSource& source, uint32_t pose) {
    if (pose >= source.num_poses()) return identity_weld(source.num_vertices());
    return weld_over_poses(source, pose, pose + 1);
}

}  // namespace nq::npr::adjacency
