#include "render/ambient_sample_points.h"

#include <algorithm>
#include <cmath>

namespace nq {

namespace {

bool in_leaf(const Bsp& bsp, uint32_t leaf, const glm::vec3& p) {
    return leaf_at(bsp, {p.x, p.y, p.z}, 0) == leaf;
}

bool open_contents(int32_t contents) {
    return contents != bsp_contents::solid && contents != bsp_contents::sky &&
           contents <= bsp_contents::empty && contents >= bsp_contents::lowest_valid;
}

bool usable_box(const BspLeaf& leaf) {
    for (int a = 0; a < 3; ++a) {
        if (!std::isfinite(leaf.mins[a]) || !std::isfinite(leaf.maxs[a])) return false;
        if (leaf.mins[a] > leaf.maxs[a]) return false;
    }
    return true;
}

// The centroid of the vertices of the faces listed on `leaf` (its marksurfaces).
bool face_centroid(const Bsp& bsp, const BspLeaf& leaf, glm::vec3& out) {
    glm::dvec3 sum(0.0);
    size_t count = 0;
    const size_t end = std::min<size_t>(size_t{leaf.first_marksurface} + leaf.num_marksurfaces,
                                        bsp.marksurfaces.size());
    for (size_t m = leaf.first_marksurface; m < end; ++m) {
        const uint32_t f = bsp.marksurfaces[m];
        if (f >= bsp.faces.size()) continue;
        const BspFace& face = bsp.faces[f];
        for (uint32_t k = 0; k < face.num_surfedges; ++k) {
            const size_t se = size_t{face.first_surfedge} + k;
            if (se >= bsp.surfedges.size()) break;
            const int32_t e = bsp.surfedges[se];
            const size_t edge = size_t(e >= 0 ? int64_t{e} : -int64_t{e});
            if (edge >= bsp.edges.size()) continue;
            const uint32_t v = bsp.edges[edge].v[e >= 0 ? 0 : 1];
            if (v >= bsp.vertices.size()) continue;
            sum += glm::dvec3(bsp.vertices[v][0], bsp.vertices[v][1], bsp.vertices[v][2]);
            ++count;
        }
    }
    if (count == 0) return false;
    out = glm::vec3(sum / double(count));
    return true;
}

glm::vec3 box_centre(const BspLeaf& leaf) {
    return {(leaf.mins[0] + leaf.maxs[0]) * 0.5f, (leaf.mins[1] + leaf.maxs[1]) * 0.5f,
            (leaf.mins[2] + leaf.maxs[2]) * 0.5f};
}

int cells_along(float extent, float spacing) {
    const float n = std::round(extent / spacing);
    return std::clamp(int(std::isfinite(n) ? n : 1.0f), 1, kMaxCellsPerAxis);
}

// Cell centres of the leaf's box that lie in the leaf.
void cell_points(const Bsp& bsp, uint32_t index, float spacing,
                 std::vector<AmbientSamplePoint>& out) {
    const BspLeaf& leaf = bsp.leafs[index];
    const glm::vec3 mins(leaf.mins[0], leaf.mins[1], leaf.mins[2]);
    const glm::vec3 size = glm::vec3(leaf.maxs[0], leaf.maxs[1], leaf.maxs[2]) - mins;
    const bool small = std::max({size.x, size.y, size.z}) < kSmallLeafExtent;
    const int n[3] = {cells_along(size.x, spacing), cells_along(size.y, spacing),
                      cells_along(size.z, spacing)};
    const size_t before = out.size();
    for (int i = 0; i < n[0]; ++i) {
        for (int j = 0; j < n[1]; ++j) {
            for (int k = 0; k < n[2]; ++k) {
                const glm::vec3 f((i + 0.5f) / n[0], (j + 0.5f) / n[1], (k + 0.5f) / n[2]);
                const glm::vec3 p = mins + size * f;
                if (in_leaf(bsp, index, p)) out.push_back({p, index, small});
            }
        }
    }
    glm::vec3 pulled;
    if (out.size() == before && point_inside_leaf(bsp, index, pulled)) {
        out.push_back({pulled, index, small});
    }
}

}  // namespace

bool point_inside_leaf(const Bsp& bsp, uint32_t index, glm::vec3& out) {
    if (index >= bsp.leafs.size() || !usable_box(bsp.leafs[index])) return false;
    const BspLeaf& leaf = bsp.leafs[index];
    const glm::vec3 centre = box_centre(leaf);
    if (in_leaf(bsp, index, centre)) {
        out = centre;
        return true;
    }
    glm::vec3 centroid;
    if (!face_centroid(bsp, leaf, centroid)) return false;
    for (float t : {0.0f, 0.5f, 0.25f, 0.75f, 0.125f, 0.0625f}) {
        const glm::vec3 p = glm::mix(centroid, centre, t);
        if (in_leaf(bsp, index, p)) {
            out = p;
            return true;
        }
    }
    return false;
}

std::vector<AmbientSamplePoint> ambient_sample_points(const Bsp& bsp, float spacing) {
    std::vector<AmbientSamplePoint> out;
    if (bsp.models.empty() || bsp.leafs.empty() || !(spacing > 0.0f)) return out;
    const size_t last = std::min<size_t>(size_t{bsp.models[0].visleafs}, bsp.leafs.size() - 1);
    for (size_t i = 1; i <= last; ++i) {
        const BspLeaf& leaf = bsp.leafs[i];
        if (!open_contents(leaf.contents) || !usable_box(leaf)) continue;
        cell_points(bsp, uint32_t(i), spacing, out);
    }
    return out;
}

}  // namespace nq
