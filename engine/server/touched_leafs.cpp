#include "server/touched_leafs.h"

namespace nq::server {

namespace {

using vm::Vec3f;

// Which sides of `plane` the box reaches: bit 0 in front (distance >= 0), bit 1 behind. Axial
// planes compare one coordinate, as Quake's BOX_ON_PLANE_SIDE does, which decides the boxes that
// just touch a plane the same way.
int box_on_plane_side(const Vec3f& mins, const Vec3f& maxs, const BspPlane& plane) {
    if (plane.type >= 0 && plane.type < 3) {
        if (plane.dist <= mins[plane.type]) return 1;
        if (plane.dist >= maxs[plane.type]) return 2;
        return 3;
    }
    float far = 0, near = 0;  // the corner furthest in front, the one furthest behind
    for (int i = 0; i < 3; ++i) {
        const bool negative = plane.normal[i] < 0;
        far += plane.normal[i] * (negative ? mins[i] : maxs[i]);
        near += plane.normal[i] * (negative ? maxs[i] : mins[i]);
    }
    int sides = 0;
    if (far >= plane.dist) sides = 1;
    if (near < plane.dist) sides |= 2;
    return sides;
}

struct LeafWalk {
    const Bsp& bsp;
    const Vec3f& mins;
    const Vec3f& maxs;
    std::span<int32_t> out;
    TouchedLeafs result;

    void add_leaf(uint32_t leaf) {
        if (leaf >= bsp.leafs.size() || bsp.leafs[leaf].contents == bsp_contents::solid) return;
        if (result.count == out.size()) {
            result.complete = false;
            return;
        }
        out[result.count++] = static_cast<int32_t>(leaf);
    }

    void visit(int32_t child, int depth) {
        if (child < 0) return add_leaf(static_cast<uint32_t>(-(child + 1)));
        if (depth > kBspMaxTreeDepth || static_cast<size_t>(child) >= bsp.nodes.size()) return;
        const BspNode& node = bsp.nodes[child];
        if (node.plane >= bsp.planes.size()) return;
        const int sides = box_on_plane_side(mins, maxs, bsp.planes[node.plane]);
        if (sides & 1) visit(node.children[0], depth + 1);
        if (sides & 2) visit(node.children[1], depth + 1);
    }
};

}  // namespace

TouchedLeafs find_touched_leafs(const Bsp& world, const Vec3f& mins, const Vec3f& maxs,
                                std::span<int32_t> out) {
    LeafWalk walk{world, mins, maxs, out, {}};
    if (!world.models.empty()) walk.visit(world.models[0].headnodes[0], 0);
    return walk.result;
}

}  // namespace nq::server
