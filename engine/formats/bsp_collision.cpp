// Queries on the collision hulls: point contents, the leaf under a point, and line traces.
// Trees were validated at load (acyclic, bounded depth), but every step here still checks its
// indices, so a hand-edited Bsp can give wrong answers but never read out of bounds.
#include <algorithm>
#include <cmath>

#include "formats/bsp.h"

namespace nq {

namespace {

// 1/32 unit: a trace stops this far in front of the plane it hits, so its end point is
// reliably outside solid when tested again.
constexpr double kTraceEpsilon = 0.03125;
constexpr double kBackOffStep = 0.1;  // fraction steps when a stop point still lands in solid

double plane_distance(const BspPlane& plane, const BspVec3& p) {
    return double{plane.normal[0]} * p[0] + double{plane.normal[1]} * p[1] +
           double{plane.normal[2]} * p[2] - plane.dist;
}

BspVec3 lerp(const BspVec3& a, const BspVec3& b, double t) {
    BspVec3 r;
    for (int i = 0; i < 3; ++i) r[i] = static_cast<float>(a[i] + t * (double{b[i]} - a[i]));
    return r;
}

bool finite(const BspVec3& v) {
    return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

// The head of `hull` in `model`, or false when either is out of range.
bool hull_head(const Bsp& bsp, int hull, size_t model, int32_t& head) {
    if (hull < 0 || hull >= static_cast<int>(bsp.hulls.size()) || model >= bsp.models.size()) {
        return false;
    }
    head = bsp.models[model].headnodes[hull];
    return true;
}

// Walks a clip tree from `node` down to its contents.
int32_t contents_from(const Bsp& bsp, const BspHull& hull, int32_t node, const BspVec3& p) {
    for (int steps = 0; node >= 0; ++steps) {
        if (steps > kBspMaxTreeDepth || static_cast<size_t>(node) >= hull.clipnodes.size()) {
            return bsp_contents::solid;
        }
        const BspClipNode& c = hull.clipnodes[node];
        if (c.plane >= bsp.planes.size()) return bsp_contents::solid;
        node = c.children[plane_distance(bsp.planes[c.plane], p) < 0 ? 1 : 0];
    }
    return node;
}

// Recursive sweep of a segment through a clip tree (the classic hull trace): split the segment
// at each plane it crosses, go down the near side first, and stop at the first point where
// the far side is solid.
struct Tracer {
    const Bsp& bsp;
    const BspHull& hull;
    int32_t head;
    BspTrace& trace;

    // Returns false once the trace has stopped.
    bool sweep(int32_t node, double f1, double f2, const BspVec3& p1, const BspVec3& p2,
               int depth) {
        if (node < 0) {
            if (node == bsp_contents::solid) {
                trace.start_solid = true;
            } else {
                trace.all_solid = false;
            }
            return true;
        }
        if (depth > kBspMaxTreeDepth || static_cast<size_t>(node) >= hull.clipnodes.size() ||
            hull.clipnodes[node].plane >= bsp.planes.size()) {
            return true;  // unreachable for a validated map; treat as a leaf of unknown contents
        }
        const BspClipNode& c = hull.clipnodes[node];
        const BspPlane& plane = bsp.planes[c.plane];
        const double d1 = plane_distance(plane, p1);
        const double d2 = plane_distance(plane, p2);
        if (d1 >= 0 && d2 >= 0) return sweep(c.children[0], f1, f2, p1, p2, depth + 1);
        if (d1 < 0 && d2 < 0) return sweep(c.children[1], f1, f2, p1, p2, depth + 1);

        const int near = d1 < 0 ? 1 : 0;
        // Split point, pulled back towards p1 by the epsilon.
        double frac =
            std::clamp((near ? d1 + kTraceEpsilon : d1 - kTraceEpsilon) / (d1 - d2), 0.0, 1.0);
        double fmid = f1 + (f2 - f1) * frac;
        BspVec3 mid = lerp(p1, p2, frac);
        if (!sweep(c.children[near], f1, fmid, p1, mid, depth + 1)) return false;
        if (contents_from(bsp, hull, c.children[near ^ 1], mid) != bsp_contents::solid) {
            return sweep(c.children[near ^ 1], fmid, f2, mid, p2, depth + 1);
        }
        if (trace.all_solid) return false;  // never got out of solid: nothing to report

        // The far side is solid: this plane is the surface hit, facing p1.
        for (int i = 0; i < 3; ++i) {
            trace.plane_normal[i] = near ? -plane.normal[i] : plane.normal[i];
        }
        trace.plane_dist = near ? -plane.dist : plane.dist;
        // On glancing hits the nudged point can still fall in solid: back off towards p1.
        while (contents_from(bsp, hull, head, mid) == bsp_contents::solid && frac > 0) {
            frac = std::max(0.0, frac - kBackOffStep);
            fmid = f1 + (f2 - f1) * frac;
            mid = lerp(p1, p2, frac);
        }
        trace.fraction = static_cast<float>(fmid);
        trace.end = mid;
        return false;
    }
};

}  // namespace

int32_t point_contents(const Bsp& bsp, int hull, const BspVec3& point, size_t model) {
    int32_t head = 0;
    if (!hull_head(bsp, hull, model, head)) return bsp_contents::solid;
    return contents_from(bsp, bsp.hulls[hull], head, point);
}

uint32_t leaf_at(const Bsp& bsp, const BspVec3& point, size_t model) {
    if (model >= bsp.models.size()) return 0;
    int32_t node = bsp.models[model].headnodes[0];
    for (int steps = 0; node >= 0; ++steps) {
        if (steps > kBspMaxTreeDepth || static_cast<size_t>(node) >= bsp.nodes.size()) return 0;
        const BspNode& n = bsp.nodes[node];
        if (n.plane >= bsp.planes.size()) return 0;
        node = n.children[plane_distance(bsp.planes[n.plane], point) < 0 ? 1 : 0];
    }
    const auto leaf = static_cast<uint32_t>(-(node + 1));
    return leaf < bsp.leafs.size() ? leaf : 0;
}

BspTrace trace_hull(const Bsp& bsp, int hull, const BspVec3& start, const BspVec3& end,
                    size_t model) {
    BspTrace trace;
    trace.end = end;
    trace.all_solid = true;
    int32_t head = 0;
    if (finite(start) && finite(end) && hull_head(bsp, hull, model, head)) {
        Tracer tracer{bsp, bsp.hulls[hull], head, trace};
        tracer.sweep(head, 0, 1, start, end, 0);
    }
    if (trace.all_solid) {  // no open space anywhere on the way: it cannot move at all
        trace.start_solid = true;
        trace.fraction = 0;
        trace.end = start;
    }
    return trace;
}

BspTrace trace_down(const Bsp& bsp, const BspVec3& from, float max_distance, int hull) {
    return trace_hull(bsp, hull, from, {from[0], from[1], from[2] - max_distance}, 0);
}

}  // namespace nq
