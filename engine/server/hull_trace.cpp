#include "server/hull_trace.h"

#include "server/qmath.h"

namespace nq::server {

namespace {

// Double precision, as trace_hull measures, so both agree on which side a point lies.
double plane_distance(const BspPlane& plane, const Vec3f& p) {
    return double{plane.normal[0]} * p[0] + double{plane.normal[1]} * p[1] +
           double{plane.normal[2]} * p[2] - plane.dist;
}

Vec3f lerp(const Vec3f& a, const Vec3f& b, double t) {
    Vec3f r;
    for (int i = 0; i < 3; ++i) r[i] = static_cast<float>(a[i] + t * (double{b[i]} - a[i]));
    return r;
}

// Quake's sweep raises in_open / in_water at every non-solid leaf it enters before it stops;
// trace_hull does not report them, so walk the leafs the travelled part p1..p2 crosses.
void mark_contents(const Bsp& bsp, const BspHull& hull, int32_t node, const Vec3f& p1,
                   const Vec3f& p2, MoveTrace& trace, int depth) {
    while (node >= 0) {
        if (depth > kBspMaxTreeDepth || static_cast<size_t>(node) >= hull.clipnodes.size() ||
            hull.clipnodes[node].plane >= bsp.planes.size()) {
            return;  // unreachable for a validated map
        }
        const BspClipNode& c = hull.clipnodes[node];
        const BspPlane& plane = bsp.planes[c.plane];
        const double d1 = plane_distance(plane, p1);
        const double d2 = plane_distance(plane, p2);
        ++depth;
        if (d1 >= 0 && d2 >= 0) {
            node = c.children[0];
        } else if (d1 < 0 && d2 < 0) {
            node = c.children[1];
        } else {
            const int near = d1 < 0 ? 1 : 0;
            const Vec3f mid = lerp(p1, p2, d1 / (d1 - d2));
            mark_contents(bsp, hull, c.children[near], p1, mid, trace, depth);
            mark_contents(bsp, hull, c.children[near ^ 1], mid, p2, trace, depth);
            return;
        }
    }
    if (node == bsp_contents::solid) return;
    if (node == bsp_contents::empty) {
        trace.in_open = true;
    } else {
        trace.in_water = true;
    }
}

}  // namespace

MoveTrace trace_placed_hull(const Bsp& bsp, int hull, size_t model, const Vec3f& offset,
                            const Vec3f& start, const Vec3f& end) {
    const Vec3f start_l = vsub(start, offset);
    const Vec3f end_l = vsub(end, offset);
    const BspTrace t = trace_hull(bsp, hull, start_l, end_l, model);
    MoveTrace r;
    r.end_pos = end;
    r.all_solid = t.all_solid;
    r.start_solid = t.start_solid;
    if (t.all_solid) return r;  // Quake keeps its default fraction 1 and end here

    r.fraction = t.fraction;
    r.plane_normal = t.plane_normal;
    r.plane_dist = t.plane_dist;  // stays in the hull's space, as in Quake
    if (t.fraction < 1) r.end_pos = vadd(t.end, offset);
    if (hull >= 0 && hull < static_cast<int>(bsp.hulls.size()) && model < bsp.models.size()) {
        mark_contents(bsp, bsp.hulls[hull], bsp.models[model].headnodes[hull], start_l,
                      t.fraction < 1 ? t.end : end_l, r, 0);
    }
    return r;
}

BoxHull::BoxHull() {
    bsp_.name = "box hull";
    bsp_.planes.resize(6);
    bsp_.models.resize(1);  // headnodes all 0: the chain starts at clipnode 0
    std::vector<BspClipNode>& nodes = bsp_.hulls[kHull].clipnodes;
    nodes.resize(6);
    for (int i = 0; i < 6; ++i) {
        const int axis = i >> 1;
        const int outside = i & 1;  // max planes: outside in front; min planes: outside behind
        bsp_.planes[i].normal[axis] = 1;
        bsp_.planes[i].type = axis;
        nodes[i].plane = static_cast<uint32_t>(i);
        nodes[i].children[outside] = bsp_contents::empty;
        nodes[i].children[outside ^ 1] = i < 5 ? i + 1 : bsp_contents::solid;
    }
}

const Bsp& BoxHull::set(const Vec3f& mins, const Vec3f& maxs) {
    for (int axis = 0; axis < 3; ++axis) {
        bsp_.planes[2 * axis].dist = maxs[axis];
        bsp_.planes[2 * axis + 1].dist = mins[axis];
    }
    return bsp_;
}

}  // namespace nq::server
