#include "adjacency/file_triangles.h"

#include <algorithm>
#include <unordered_map>

namespace nq::npr::adjacency {

namespace {

std::vector<FileTriangle> usable_triangles(const AliasSource& source) {
    std::vector<FileTriangle> out;
    out.reserve(source.num_triangles());
    for (uint32_t t = 0; t < source.num_triangles(); ++t) {
        const auto& c = source.triangle(t).vertices;
        if (!source.vertex_in_range(c[0]) || !source.vertex_in_range(c[1]) ||
            !source.vertex_in_range(c[2])) {
            continue;
        }
        if (c[0] == c[1] || c[1] == c[2] || c[2] == c[0]) continue;
        out.push_back({uint32_t(c[0]), uint32_t(c[2]), uint32_t(c[1])});
    }
    return out;
}

// Per MDL vertex, an id shared by every MDL vertex at the same welded position; vertices no
// face of the mesh uses keep an id of their own.
std::vector<uint32_t> welded_ids(const BuiltMesh& built, uint32_t vertex_count) {
    constexpr uint32_t kOwnId = 0x80000000u;
    std::vector<uint32_t> ids(vertex_count);
    for (uint32_t v = 0; v < vertex_count; ++v) ids[v] = kOwnId | v;
    for (size_t f = 0; f < built.face_corners.size(); ++f) {
        for (int k = 0; k < 3; ++k) {
            const uint32_t mdl = built.face_corners[f][k];
            const uint32_t mesh_vertex = built.face_vertices[f][k];
            if (mdl < vertex_count && mesh_vertex < built.vertex_welded.size()) {
                ids[mdl] = built.vertex_welded[mesh_vertex];
            }
        }
    }
    return ids;
}

std::vector<uint32_t> first_of_each_id(const std::vector<uint32_t>& ids) {
    std::unordered_map<uint32_t, uint32_t> first;
    std::vector<uint32_t> out(ids.size());
    for (uint32_t v = 0; v < ids.size(); ++v) out[v] = first.emplace(ids[v], v).first->second;
    return out;
}

std::vector<std::array<int32_t, 3>> side_twins(const std::vector<FileTriangle>& tris,
                                               const std::vector<uint32_t>& ids) {
    struct Side {
        uint32_t lo, hi, triangle, k;
        bool operator<(const Side& o) const { return lo != o.lo ? lo < o.lo : hi < o.hi; }
    };
    const auto id = [&](uint32_t t, uint32_t k) { return ids[tris[t][k % 3]]; };
    std::vector<Side> sides;
    sides.reserve(tris.size() * 3);
    for (uint32_t t = 0; t < tris.size(); ++t) {
        for (uint32_t k = 0; k < 3; ++k) {
            const uint32_t a = id(t, k), b = id(t, k + 1);
            if (a != b) sides.push_back({std::min(a, b), std::max(a, b), t, k});
        }
    }
    std::sort(sides.begin(), sides.end());
    std::vector<std::array<int32_t, 3>> twins(tris.size(), {-1, -1, -1});
    for (size_t i = 0; i < sides.size();) {
        size_t j = i;
        while (j < sides.size() && sides[j].lo == sides[i].lo && sides[j].hi == sides[i].hi) ++j;
        if (j - i == 2) {
            const Side &x = sides[i], &y = sides[i + 1];
            if (id(x.triangle, x.k) == id(y.triangle, y.k + 1)) {  // x runs a->b, y b->a
                twins[x.triangle][x.k] = static_cast<int32_t>(y.triangle);
                twins[y.triangle][y.k] = static_cast<int32_t>(x.triangle);
            }
        }
        i = j;
    }
    return twins;
}

}  // namespace

FileTriangles describe_file_triangles(const AliasSource& source, const BuiltMesh& built) {
    FileTriangles out;
    out.triangles = usable_triangles(source);
    const std::vector<uint32_t> ids = welded_ids(built, source.num_vertices());
    out.twins = side_twins(out.triangles, ids);
    out.seam_representatives = first_of_each_id(ids);
    return out;
}

}  // namespace nq::npr::adjacency
