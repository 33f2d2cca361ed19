// Synthetic alias models for the adjacency tests, built directly as nqr_alias_model views (the
// form renderers receive), with shapes whose edges, creases and silhouettes are known by
// construction. Positions are packed bytes; model space = scale * packed + origin.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include <glm/vec3.hpp>

#include "adjacency/model_adjacency.h"
#include "nqr_renderer.h"

namespace nq::test {

using Packed = std::array<uint8_t, 3>;

class SyntheticAlias {
  public:
    explicit SyntheticAlias(std::vector<std::vector<Packed>> poses, glm::vec3 scale = glm::vec3(1),
                            glm::vec3 origin = glm::vec3(0))
        : poses_(std::move(poses)), scale_(scale), origin_(origin) {}

    // As Quake stores triangles: clockwise seen from outside.
    void add_stored(uint32_t a, uint32_t b, uint32_t c, int32_t faces_front = 1) {
        triangles_.insert(triangles_.end(), {faces_front, int32_t(a), int32_t(b), int32_t(c)});
    }
    // Counter-clockwise seen from outside, as geometry is usually written: stored reversed.
    void add_outward(uint32_t a, uint32_t b, uint32_t c) { add_stored(a, c, b); }
    void add_outward_quad(uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
        add_outward(a, b, c);
        add_outward(a, c, d);
    }
    uint32_t num_triangles() const { return uint32_t(triangles_.size() / 4); }

    // Valid until the next change to this object.
    const nqr_alias_model& view() {
        const uint32_t num_vertices = poses_.empty() ? 0 : uint32_t(poses_[0].size());
        packed_.clear();
        frames_.clear();
        for (uint32_t p = 0; p < poses_.size(); ++p) {
            for (const Packed& v : poses_[p]) packed_.push_back({{v[0], v[1], v[2]}, 0});
            nqr_alias_frame f{};
            f.size = sizeof f;
            f.name = "pose";
            f.first_pose = p;
            f.num_poses = 1;
            f.intervals = &kInterval;
            frames_.push_back(f);
        }
        st_.assign(size_t(num_vertices) * 3, 0);
        model_ = nqr_alias_model{};
        model_.size = sizeof model_;
        for (int i = 0; i < 3; ++i) {
            model_.scale[i] = scale_[i];
            model_.origin[i] = origin_[i];
        }
        model_.skin_width = 8;
        model_.skin_height = 8;
        model_.num_vertices = num_vertices;
        model_.num_triangles = num_triangles();
        model_.num_poses = uint32_t(poses_.size());
        model_.num_frames = uint32_t(poses_.size());
        model_.st = st_.empty() ? nullptr : st_.data();
        model_.triangles = triangles_.empty() ? nullptr : triangles_.data();
        model_.poses = packed_.empty() ? nullptr : packed_.data();
        model_.frames = frames_.empty() ? nullptr : frames_.data();
        return model_;
    }

    npr::adjacency::ModelAdjacency recover(const npr::adjacency::RecoveryOptions& options = {}) {
        return npr::adjacency::recover_adjacency(view(), options);
    }
    // Model-space positions of every vertex in `pose`, computed here from the packed bytes.
    std::vector<glm::vec3> positions(uint32_t pose) const {
        std::vector<glm::vec3> out;
        for (const Packed& p : poses_[pose]) {
            out.push_back(scale_ * glm::vec3(p[0], p[1], p[2]) + origin_);
        }
        return out;
    }

  private:
    static constexpr float kInterval = 0.1f;
    std::vector<std::vector<Packed>> poses_;
    glm::vec3 scale_, origin_;
    std::vector<int32_t> triangles_;
    std::vector<int32_t> st_;
    std::vector<nqr_alias_vertex> packed_;
    std::vector<nqr_alias_frame> frames_;
    nqr_alias_model model_{};
};

// Corner i of a cube of side `size` at the packed origin: bit 0 = x, bit 1 = y, bit 2 = z.
inline Packed cube_corner(uint32_t i, uint8_t size = 20) {
    return {uint8_t(i & 1 ? size : 0), uint8_t(i & 2 ? size : 0), uint8_t(i & 4 ? size : 0)};
}

// The six faces of that cube as quads of corner indices, counter-clockwise from outside:
// -x, +x, -y, +y, -z, +z.
inline constexpr std::array<std::array<uint32_t, 4>, 6> kCubeQuads{
    {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}}};

// A 20-unit cube centred on the model origin. With seams, every face has its own four vertices
// (24 in all, three at each corner), as MDL files store texture seams.
inline SyntheticAlias cube_model(bool seam_duplicates = false) {
    std::vector<Packed> vertices;
    if (!seam_duplicates) {
        for (uint32_t i = 0; i < 8; ++i) vertices.push_back(cube_corner(i));
    } else {
        for (const auto& quad : kCubeQuads) {
            for (uint32_t corner : quad) vertices.push_back(cube_corner(corner));
        }
    }
    SyntheticAlias model({vertices}, glm::vec3(1), glm::vec3(-10));
    for (uint32_t f = 0; f < 6; ++f) {
        const auto& q = kCubeQuads[f];
        if (seam_duplicates) {
            model.add_outward_quad(4 * f, 4 * f + 1, 4 * f + 2, 4 * f + 3);
        } else {
            model.add_outward_quad(q[0], q[1], q[2], q[3]);
        }
    }
    return model;
}

// An L-shaped step: the profile (x, z) = (0,0) (30,0) (30,10) (10,10) (10,30) (0,30) extruded
// 20 along y. Vertex i < 6 is profile point i at y = 0, vertex i + 6 the same at y = 20. Its only
// concave edge is the inner corner (10, 10): vertices 3 and 9.
inline SyntheticAlias l_step_model() {
    const std::array<std::array<uint8_t, 2>, 6> profile{
        {{0, 0}, {30, 0}, {30, 10}, {10, 10}, {10, 30}, {0, 30}}};
    std::vector<Packed> vertices;
    for (uint8_t y : {uint8_t(0), uint8_t(20)}) {
        for (const auto& p : profile) vertices.push_back({p[0], y, p[1]});
    }
    SyntheticAlias model({vertices});
    // The profile runs counter-clockwise in (x, z), which faces -y: the front cap as is, the
    // back cap reversed; each cap is a fan of four triangles from profile point 0.
    for (uint32_t i = 1; i + 1 < 6; ++i) {
        model.add_outward(0, i, i + 1);
        model.add_outward(6, 6 + i + 1, 6 + i);
    }
    for (uint32_t i = 0; i < 6; ++i) {
        const uint32_t j = (i + 1) % 6;
        model.add_outward_quad(i, 6 + i, 6 + j, j);
    }
    return model;
}

// A UV sphere of radius 100 around packed (128, 128, 128): vertex 0 the north pole (+z),
// vertex 1 the south pole, then ring r = 1..stacks-1 from north to south, slice s at longitude
// 2 pi s / slices: vertex 2 + (r - 1) * slices + s. With an even number of stacks, ring
// stacks / 2 is the equator.
inline uint32_t sphere_vertex(uint32_t ring, uint32_t slice, uint32_t slices, uint32_t stacks) {
    if (ring == 0) return 0;
    if (ring == stacks) return 1;
    return 2 + (ring - 1) * slices + slice % slices;
}

inline SyntheticAlias sphere_model(uint32_t slices, uint32_t stacks, glm::vec3 origin) {
    auto packed = [](double v) { return uint8_t(std::lround(128.0 + 100.0 * v)); };
    std::vector<Packed> vertices{{128, 128, 228}, {128, 128, 28}};
    for (uint32_t r = 1; r < stacks; ++r) {
        const double latitude = std::numbers::pi / 2 - std::numbers::pi * r / stacks;
        for (uint32_t s = 0; s < slices; ++s) {
            const double longitude = 2 * std::numbers::pi * s / slices;
            vertices.push_back({packed(std::cos(latitude) * std::cos(longitude)),
                                packed(std::cos(latitude) * std::sin(longitude)),
                                packed(std::sin(latitude))});
        }
    }
    SyntheticAlias model({vertices}, glm::vec3(1), origin);
    for (uint32_t r = 0; r < stacks; ++r) {
        for (uint32_t s = 0; s < slices; ++s) {
            const uint32_t a = sphere_vertex(r, s, slices, stacks);
            const uint32_t b = sphere_vertex(r + 1, s, slices, stacks);
            const uint32_t c = sphere_vertex(r + 1, s + 1, slices, stacks);
            const uint32_t d = sphere_vertex(r, s + 1, slices, stacks);
            if (r == 0) {
                model.add_outward(a, b, c);
            } else if (r + 1 == stacks) {
                model.add_outward(a, b, d);
            } else {
                model.add_outward_quad(a, b, c, d);
            }
        }
    }
    return model;
}

}  // namespace nq::test
