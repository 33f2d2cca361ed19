#include "adjacency/triangle_filter.h"

#include <algorithm>
#include <unordered_map>

#include "adjacency/degenerate.h"

namespace nq::npr::adjacency {

namespace {

// The welded vertices sorted, and whether sorting them took an odd permutation (the
// orientation, up to rotation).
struct VertexSetKey {
    std::array<uint32_t, 3> sorted{};
    bool odd = false;
};

VertexSetKey vertex_set_key(std::array<uint32_t, 3> v) {
    VertexSetKey key;
    auto swap_if = [&](int i, int j) {
        if (v[i] > v[j]) {
            std::swap(v[i], v[j]);
            key.odd = !key.odd;
        }
    };
    swap_if(0, 1);
    swap_if(1, 2);
    swap_if(0, 1);
    key.sorted = v;
    return key;
}

struct SortedHash {
    size_t operator()(const std::array<uint32_t, 3>& v) const {
        uint64_t h = v[0];
        h = h * 0x9E3779B97F4A7C15ull + v[1];
        h = h * 0x9E3779B97F4A7C15ull + v[2];
        return static_cast<size_t>(h ^ (h >> 29));
    }
};

TriangleFate degeneracy(const AliasSource& source, const VertexWeld& weld, const AliasTriangle& t) {
    for (int32_t v : t.vertices) {
        if (!source.vertex_in_range(v)) return TriangleFate::bad_index;
    }
    const auto& v = t.vertices;
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) return TriangleFate::repeated_index;
    const uint32_t a = weld.class_of[v[0]], b = weld.class_of[v[1]], c = weld.class_of[v[2]];
    if (a == b || b == c || a == c) return TriangleFate::collapsed_by_weld;
    const std::array<uint32_t, 3> mdl{uint32_t(v[0]), uint32_t(v[1]), uint32_t(v[2])};
    if (zero_area_in_every_pose(source, mdl)) return TriangleFate::zero_area;
    return TriangleFate::kept;
}

void count(TriangleFilterCounts& counts, TriangleFate fate) {
    switch (fate) {
        case TriangleFate::kept:
            break;
        case TriangleFate::bad_index:
            ++counts.bad_index;
            break;
        case TriangleFate::repeated_index:
            ++counts.repeated_index;
            break;
        case TriangleFate::collapsed_by_weld:
            ++counts.collapsed_by_weld;
            break;
        case TriangleFate::zero_area:
            ++counts.zero_area;
            break;
        case TriangleFate::exact_duplicate:
            ++counts.exact_duplicates;
            break;
        case TriangleFate::back_to_back_twin:
            ++counts.back_to_back_twins;
            break;
    }
}

}  // namespace

const char* fate_name(TriangleFate fate) {
    switch (fate) {
        case TriangleFate::kept:
            return "kept";
        case TriangleFate::bad_index:
            return "bad vertex index";
        case TriangleFate::repeated_index:
            return "repeated vertex index";
        case TriangleFate::collapsed_by_weld:
            return "collapsed by weld";
        case TriangleFate::zero_area:
            return "zero area in every pose";
        case TriangleFate::exact_duplicate:
            return "exact duplicate";
        case TriangleFate::back_to_back_twin:
            return "back-to-back twin";
    }
    return "?";
}

FilteredTriangles filter_triangles(const AliasSource& source, const VertexWeld& weld) {
    FilteredTriangles out;
    out.fate.resize(source.num_triangles(), TriangleFate::kept);
    out.kept.reserve(source.num_triangles());
    // First kept triangle of each welded vertex set, with its orientation.
    std::unordered_map<std::array<uint32_t, 3>, bool, SortedHash> seen;
    seen.reserve(source.num_triangles());
    for (uint32_t i = 0; i < source.num_triangles(); ++i) {
        const AliasTriangle t = source.triangle(i);
        TriangleFate fate = degeneracy(source, weld, t);
        if (fate == TriangleFate::kept) {
            SoupTriangle kept;
            kept.mdl_triangle = i;
            for (int k = 0; k < 3; ++k) {
                kept.mdl_vertices[k] = static_cast<uint32_t>(t.vertices[k]);
                kept.welded[k] = weld.class_of[kept.mdl_vertices[k]];
            }
            const VertexSetKey key = vertex_set_key(kept.welded);
            const auto [it, inserted] = seen.emplace(key.sorted, key.odd);
            if (inserted) {
                out.kept.push_back(kept);
            } else {
                fate = it->second == key.odd ? TriangleFate::exact_duplicate
                                             : TriangleFate::back_to_back_twin;
            }
        }
        out.fate[i] = fate;
        count(out.counts, fate);
    }
    return out;
}

}  // namespace nq::npr::adjacency
