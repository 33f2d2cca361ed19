// Silhouettes and creases of brush geometry (nprlib/technical: BrushEdgeTable, BrushEdgeMesh,
// BrushEdgeDrawer). Adjacency on synthetic brushes (a box, an L-shaped step, a T-junction, a
// waterline where four faces meet, a side ending inside a face, pieces that only line up) and on
// LibreQuake's maps, checked against geometry computed here (every open edge open for a reason
// the map's data shows); then the edges drawn offscreen: ridge, valley and silhouette
// colours where this file's own projection puts the box's edges, nothing on hidden ones, the
// ridge colour from the texture's smallest mip, no allocation per frame, and the time per frame.
#include "support/allocation_counter.h"  // replaces operator new for this executable

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <numeric>
#include <unordered_map>

#include "abi/frame_view.h"
#include "common/file_io.h"
#include "formats/bsp.h"
#include "formats/entities.h"
#include "gl/program.h"
#include "render/brush_model.h"
#include "render/frustum.h"
#include "render/world_culler.h"
#include "support/nprlib_test_support.h"
#include "support/test_data.h"
#include "technical/brush_edge_drawer.h"
#include "technical/brush_edge_mesh.h"
#include "technical/brush_edge_table.h"

namespace nq::npr::test {
namespace {

using technical::BrushEdge;
using technical::BrushEdgeDrawer;
using technical::BrushEdgeMesh;
using technical::BrushEdgeStats;
using technical::BrushEdgeTable;
using technical::EdgeColorMode;
using technical::EdgeFrameUniforms;
using technical::EdgeSettings;

constexpr float kAngleTolerance = 0.01f;  // degrees
constexpr float kPointTolerance = 0.15f;  // world units: the matcher's 0.1 plus rounding

// ------------------------------------------------------------------ geometry, computed here

float distance_to_segment(glm::vec3 p, glm::vec3 a, glm::vec3 b) {
    const glm::vec3 ab = b - a;
    const float t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
    return glm::length(p - (a + ab * t));
}

// Whether p lies on the outline of the polygon (within the tolerance).
bool on_outline(const std::vector<glm::vec3>& polygon, glm::vec3 p) {
    for (size_t i = 0; i < polygon.size(); ++i) {
        if (distance_to_segment(p, polygon[i], polygon[(i + 1) % polygon.size()]) <=
            kPointTolerance) {
            return true;
        }
    }
    return false;
}

glm::vec3 newell_normal(const std::vector<glm::vec3>& polygon) {
    glm::vec3 n(0.0f);
    for (size_t i = 0; i < polygon.size(); ++i) {
        const glm::vec3& a = polygon[i];
        const glm::vec3& b = polygon[(i + 1) % polygon.size()];
        n += glm::vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x),
                       (a.x - b.x) * (a.y + b.y));
    }
    return glm::normalize(n);
}

bool same_point(glm::vec3 a, glm::vec3 b) {
    return glm::length(a - b) <= 1e-3f;
}

// ------------------------------------------------------------------ a brush from polygons

// An nqr_brush_model from explicit polygons over shared vertex ids. add_polygon() orders the
// corners so that their Newell normal points to `facing` (the ABI's counter-clockwise seen from
// the front). One 16 x 16 texture: mip 0 all `mip0_index`, the 2 x 2 mip 3 as given.
class PolygonBrush {
  public:
    PolygonBrush(uint8_t mip0_index = colour::kRed,
                 std::array<uint8_t, 4> mip3 = {colour::kRed, colour::kRed, colour::kRed,
                                                colour::kRed}) {
        for (int level = 0; level < 4; ++level) {
            const int side = 16 >> level;
            mips_[level].assign(side * side, level == 3 ? mip3[0] : mip0_index);
        }
        std::copy(mip3.begin(), mip3.end(), mips_[3].begin());
    }

    uint32_t vertex(glm::vec3 p) {
        points_.push_back(p);
        return static_cast<uint32_t>(points_.size() - 1);
    }

    uint32_t add_polygon(std::vector<uint32_t> ids, glm::vec3 facing, uint32_t flags = 0) {
        std::vector<glm::vec3> corners;
        for (uint32_t id : ids) corners.push_back(points_[id]);
        if (glm::dot(newell_normal(corners), facing) < 0.0f) {
            std::reverse(ids.begin(), ids.end());
        }
        polygons_.push_back(std::move(ids));
        flags_.push_back(flags);
        return static_cast<uint32_t>(polygons_.size() - 1);
    }

    void set_flags(uint32_t polygon, uint32_t flags) { flags_[polygon] = flags; }

    const nqr_brush_model& build() {
        surfaces_.clear();
        positions_.clear();
        vertex_ids_.clear();
        for (size_t s = 0; s < polygons_.size(); ++s) {
            nqr_surface surface{};
            surface.size = sizeof(nqr_surface);
            surface.first_vertex = static_cast<uint32_t>(vertex_ids_.size());
            surface.num_vertices = static_cast<uint32_t>(polygons_[s].size());
            const std::vector<glm::vec3> corners = outline(static_cast<uint32_t>(s));
            const glm::vec3 n = newell_normal(corners);
            std::copy_n(glm::value_ptr(n), 3, surface.normal);
            surface.dist = glm::dot(n, corners[0]);
            surface.texture = 0;
            surface.flags = flags_[s];
            surface.light_offset = -1;
            for (uint32_t id : polygons_[s]) {
                positions_.insert(positions_.end(), {points_[id].x, points_[id].y, points_[id].z});
                vertex_ids_.push_back(id);
            }
            surfaces_.push_back(surface);
        }
        texture_ = nqr_texture{};
        texture_.size = sizeof(nqr_texture);
        texture_.name = "test";
        texture_.width = texture_.height = 16;
        for (int level = 0; level < 4; ++level) texture_.mips[level] = mips_[level].data();
        brush_ = nqr_brush_model{};
        brush_.size = sizeof(nqr_brush_model);
        brush_.num_surfaces = static_cast<uint32_t>(surfaces_.size());
        brush_.surfaces = surfaces_.data();
        brush_.num_vertices = static_cast<uint32_t>(vertex_ids_.size());
        brush_.positions = positions_.data();
        brush_.vertex_ids = vertex_ids_.data();
        brush_.num_textures = 1;
        brush_.textures = &texture_;
        return brush_;
    }

    std::vector<glm::vec3> outline(uint32_t surface) const {
        std::vector<glm::vec3> corners;
        for (uint32_t id : polygons_[surface]) corners.push_back(points_[id]);
        return corners;
    }
    glm::vec3 point(uint32_t id) const { return points_[id]; }
    uint32_t num_polygons() const { return static_cast<uint32_t>(polygons_.size()); }

  private:
    std::vector<glm::vec3> points_;
    std::vector<std::vector<uint32_t>> polygons_;
    std::vector<uint32_t> flags_;
    std::array<std::vector<uint8_t>, 4> mips_;
    std::vector<nqr_surface> surfaces_;
    std::vector<float> positions_;
    std::vector<uint32_t> vertex_ids_;
    nqr_texture texture_{};
    nqr_brush_model brush_{};
};

// Box corners: bit 0 picks x, bit 1 y, bit 2 z (0 = lo, 1 = hi).
glm::vec3 box_corner(glm::vec3 lo, glm::vec3 hi, int corner) {
    return {corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y, corner & 4 ? hi.z : lo.z};
}

struct BoxFace {
    int corners[4];
    glm::vec3 outward;
};
constexpr BoxFace kBoxFaces[6] = {{{0, 2, 3, 1}, {0, 0, -1}}, {{4, 5, 7, 6}, {0, 0, 1}},
                                  {{0, 1, 5, 4}, {0, -1, 0}}, {{2, 6, 7, 3}, {0, 1, 0}},
                                  {{0, 4, 6, 2}, {-1, 0, 0}}, {{1, 3, 7, 5}, {1, 0, 0}}};

// Six quads; facing out of the box, or into it for a room.
void add_box(PolygonBrush& brush, glm::vec3 lo, glm::vec3 hi, bool room) {
    uint32_t ids[8];
    for (int c = 0; c < 8; ++c) ids[c] = brush.vertex(box_corner(lo, hi, c));
    for (const BoxFace& face : kBoxFaces) {
        std::vector<uint32_t> quad;
        for (int c : face.corners) quad.push_back(ids[c]);
        brush.add_polygon(quad, room ? -face.outward : face.outward);
    }
}

// The 12 box edges as corner pairs (differing in one bit), with the two faces holding them.
struct BoxEdge {
    int a, b;
    int faces[2];
};

std::vector<BoxEdge> box_edges() {
    std::vector<BoxEdge> edges;
    for (int a = 0; a < 8; ++a) {
        for (int bit = 1; bit < 8; bit <<= 1) {
            const int b = a | bit;
            if (b == a) continue;
            BoxEdge edge{a, b, {-1, -1}};
            int found = 0;
            for (int f = 0; f < 6; ++f) {
                const int* c = kBoxFaces[f].corners;
                const bool has_a = std::find(c, c + 4, a) != c + 4;
                const bool has_b = std::find(c, c + 4, b) != c + 4;
                if (has_a && has_b) edge.faces[found++] = f;
            }
            edges.push_back(edge);
        }
    }
    return edges;
}

const BrushEdge* find_edge(const BrushEdgeTable& table, glm::vec3 p, glm::vec3 q) {
    for (const BrushEdge& e : table.edges()) {
        if ((same_point(e.v0, p) && same_point(e.v1, q)) ||
            (same_point(e.v0, q) && same_point(e.v1, p))) {
            return &e;
        }
    }
    return nullptr;
}

int count_with_dihedral(const BrushEdgeTable& table, float degrees) {
    return static_cast<int>(
        std::count_if(table.edges().begin(), table.edges().end(), [&](const BrushEdge& e) {
            return !e.is_boundary() && std::abs(e.dihedral_degrees - degrees) < kAngleTolerance;
        }));
}

BrushEdgeTable build_table(const nqr_brush_model& brush) {
    std::string error;
    BrushEdgeTable table = BrushEdgeTable::build(brush, error);
    EXPECT_TRUE(error.empty()) << error;
    return table;
}

// ------------------------------------------------------------------ adjacency, synthetic

TEST(BrushEdgeTableTest, BoxHasTwelveRidgesBetweenTheFacesThatHoldThem) {
    PolygonBrush brush;
    const glm::vec3 lo(-16.0f), hi(16.0f);
    add_box(brush, lo, hi, false);
    const BrushEdgeTable table = build_table(brush.build());
    const BrushEdgeStats& stats = table.stats();
    EXPECT_EQ(stats.surfaces, 6u);
    EXPECT_EQ(stats.half_edges, 24u);
    EXPECT_EQ(stats.shared_edges, 12u);
    EXPECT_EQ(stats.unmatched_half_edges, 0u);
    EXPECT_EQ(stats.t_junction_edges, 0u);
    EXPECT_EQ(stats.boundary_edges, 0u);
    EXPECT_EQ(stats.edges, 12u);
    EXPECT_EQ(stats.creases, 12u);
    ASSERT_EQ(table.edges().size(), 12u);
    for (const BoxEdge& expected : box_edges()) {
        const glm::vec3 p = box_corner(lo, hi, expected.a), q = box_corner(lo, hi, expected.b);
        const BrushEdge* edge = find_edge(table, p, q);
        ASSERT_NE(edge, nullptr) << expected.a << "-" << expected.b;
        EXPECT_NEAR(edge->dihedral_degrees, 90.0f, kAngleTolerance);
        EXPECT_EQ(std::min(edge->face0, edge->face1),
                  static_cast<uint32_t>(std::min(expected.faces[0], expected.faces[1])));
        EXPECT_EQ(std::max(edge->face0, edge->face1),
                  static_cast<uint32_t>(std::max(expected.faces[0], expected.faces[1])));
        // v0 -> v1 is the way face0 walks it: consecutive in its outline.
        const std::vector<glm::vec3> outline = brush.outline(edge->face0);
        bool walked = false;
        for (size_t i = 0; i < outline.size(); ++i) {
            walked |= same_point(outline[i], edge->v0) &&
                      same_point(outline[(i + 1) % outline.size()], edge->v1);
        }
        EXPECT_TRUE(walked);
    }
}

TEST(BrushEdgeTableTest, RoomSeenFromInsideHasValleysOnly) {
    PolygonBrush brush;
    add_box(brush, glm::vec3(-64.0f), glm::vec3(64.0f), true);
    const BrushEdgeTable table = build_table(brush.build());
    EXPECT_EQ(table.stats().shared_edges, 12u);
    EXPECT_EQ(table.stats().creases, 12u);
    EXPECT_EQ(count_with_dihedral(table, -90.0f), 12);
}

// An L-shaped step: the profile (x, z) P0 (0,0) P1 (2,0) P2 (2,1) P3 (1,1) P4 (1,2) P5 (0,2),
// x 16 units, extruded along y over 16 units. Caps are split in two convex parts at
// Q (0,1)-P3, the back wall at Q too, so every side is shared by vertex ids.
TEST(BrushEdgeTableTest, StepHasOneValleyAtItsInnerCorner) {
    PolygonBrush brush;
    const glm::vec2 profile[7] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}, {0, 1}};
    uint32_t front[7], back[7];  // y = 0 and y = 16
    for (int i = 0; i < 7; ++i) {
        front[i] = brush.vertex({profile[i].x * 16.0f, 0.0f, profile[i].y * 16.0f});
        back[i] = brush.vertex({profile[i].x * 16.0f, 16.0f, profile[i].y * 16.0f});
    }
    const auto side = [&](int i, int j, glm::vec3 out) {
        brush.add_polygon({front[i], front[j], back[j], back[i]}, out);
    };
    side(0, 1, {0, 0, -1});  // bottom
    side(1, 2, {1, 0, 0});
    side(2, 3, {0, 0, 1});  // the lower tread
    side(3, 4, {1, 0, 0});  // the riser
    side(4, 5, {0, 0, 1});
    side(5, 6, {-1, 0, 0});  // the back wall, upper and lower half
    side(6, 0, {-1, 0, 0});
    for (const auto& [ids, out] :
         {std::pair{front, glm::vec3(0, -1, 0)}, std::pair{back, glm::vec3(0, 1, 0)}}) {
        brush.add_polygon({ids[0], ids[1], ids[2], ids[3], ids[6]}, out);
        brush.add_polygon({ids[6], ids[3], ids[4], ids[5]}, out);
    }
    const BrushEdgeTable table = build_table(brush.build());
    // 7 lengthwise edges, 8 per cap (7 outline + the split).
    EXPECT_EQ(table.stats().half_edges, 46u);
    EXPECT_EQ(table.stats().shared_edges, 23u);
    EXPECT_EQ(table.stats().boundary_edges, 0u);
    EXPECT_EQ(count_with_dihedral(table, -90.0f), 1);
    EXPECT_EQ(count_with_dihedral(table, 90.0f), 19);
    EXPECT_EQ(count_with_dihedral(table, 0.0f), 3);
    EXPECT_EQ(table.stats().creases, 20u);
    const BrushEdge* inner = find_edge(table, brush.point(front[3]), brush.point(back[3]));
    ASSERT_NE(inner, nullptr);
    EXPECT_NEAR(inner->dihedral_degrees, -90.0f, kAngleTolerance);
}

// A floor quad A (0..32 x 0..32) whose side x = 32 meets two wall quads B (y 0..16) and
// C (y 16..32) rising from it: A has no vertex at (32, 16, 0), a T-junction.
TEST(BrushEdgeTableTest, TJunctionSidesShareTheirOverlaps) {
    PolygonBrush brush;
    const uint32_t a0 = brush.vertex({0, 0, 0}), a1 = brush.vertex({32, 0, 0}),
                   a2 = brush.vertex({32, 32, 0}), a3 = brush.vertex({0, 32, 0});
    const uint32_t mid = brush.vertex({32, 16, 0});
    const uint32_t t0 = brush.vertex({32, 0, 16}), t1 = brush.vertex({32, 16, 16}),
                   t2 = brush.vertex({32, 32, 16});
    const uint32_t floor = brush.add_polygon({a0, a1, a2, a3}, {0, 0, 1});
    const uint32_t wall_b = brush.add_polygon({a1, mid, t1, t0}, {-1, 0, 0});
    const uint32_t wall_c = brush.add_polygon({mid, a2, t2, t1}, {-1, 0, 0});
    const BrushEdgeTable table = build_table(brush.build());
    const BrushEdgeStats& stats = table.stats();
    EXPECT_EQ(stats.half_edges, 12u);
    EXPECT_EQ(stats.shared_edges, 1u);  // B-C
    EXPECT_EQ(stats.unmatched_half_edges, 10u);
    EXPECT_EQ(stats.t_junction_edges, 2u);
    EXPECT_EQ(stats.boundary_edges, 7u);  // A: 3, B: 2, C: 2
    EXPECT_EQ(stats.edges, 10u);

    const BrushEdge* ab = find_edge(table, {32, 0, 0}, {32, 16, 0});
    const BrushEdge* ac = find_edge(table, {32, 16, 0}, {32, 32, 0});
    ASSERT_NE(ab, nullptr);
    ASSERT_NE(ac, nullptr);
    EXPECT_EQ(ab->face0, floor);
    EXPECT_EQ(ab->face1, wall_b);
    EXPECT_EQ(ac->face0, floor);
    EXPECT_EQ(ac->face1, wall_c);
    // The floor walks its side x = 32 towards +y; the wall rises on the floor's side: valleys.
    EXPECT_TRUE(same_point(ab->v0, {32, 0, 0}) && same_point(ab->v1, {32, 16, 0}));
    EXPECT_TRUE(same_point(ac->v0, {32, 16, 0}) && same_point(ac->v1, {32, 32, 0}));
    EXPECT_NEAR(ab->dihedral_degrees, -90.0f, kAngleTolerance);
    EXPECT_NEAR(ac->dihedral_degrees, -90.0f, kAngleTolerance);
    const BrushEdge* bc = find_edge(table, {32, 16, 0}, {32, 16, 16});
    ASSERT_NE(bc, nullptr);
    EXPECT_NEAR(bc->dihedral_degrees, 0.0f, kAngleTolerance);
}

// A wall (x = 0, facing +x) split at a waterline z = 0, and the water's two faces (up and down)
// on the same two vertex ids: four half-edges on one line. Each wall half pairs with the water
// face it meets through open space (above: the top, below: the bottom), not with its other half.
TEST(BrushEdgeTableTest, WaterlinePairsEachWallHalfWithTheWaterFaceItMeets) {
    PolygonBrush brush;
    const uint32_t l0 = brush.vertex({0, 0, 0}), l1 = brush.vertex({0, 32, 0});
    const uint32_t up0 = brush.vertex({0, 0, 32}), up1 = brush.vertex({0, 32, 32});
    const uint32_t down0 = brush.vertex({0, 0, -32}), down1 = brush.vertex({0, 32, -32});
    const uint32_t far0 = brush.vertex({32, 0, 0}), far1 = brush.vertex({32, 32, 0});
    const uint32_t above = brush.add_polygon({l0, l1, up1, up0}, {1, 0, 0});
    const uint32_t below = brush.add_polygon({l0, l1, down1, down0}, {1, 0, 0});
    const uint32_t top = brush.add_polygon({l0, l1, far1, far0}, {0, 0, 1}, NQR_SURFACE_LIQUID);
    const uint32_t bottom = brush.add_polygon({l0, l1, far1, far0}, {0, 0, -1}, NQR_SURFACE_LIQUID);
    const BrushEdgeTable table = build_table(brush.build());
    std::vector<const BrushEdge*> on_line;
    for (const BrushEdge& e : table.edges()) {
        if (!e.is_boundary() && std::abs(e.v0.x) < 1e-3f && std::abs(e.v0.z) < 1e-3f &&
            std::abs(e.v1.x) < 1e-3f && std::abs(e.v1.z) < 1e-3f) {
            on_line.push_back(&e);
        }
    }
    ASSERT_EQ(on_line.size(), 2u);
    for (const BrushEdge* e : on_line) {
        const bool above_top = e->face0 == above && e->face1 == top;
        const bool below_bottom = e->face0 == below && e->face1 == bottom;
        EXPECT_TRUE(above_top || below_bottom) << e->face0 << "-" << e->face1;
        EXPECT_NEAR(e->dihedral_degrees, -90.0f, kAngleTolerance);
    }
}

// A wall in the plane x = 0 (facing +x) split at y = 0 into W1 (a pentagon with an extra vertex M
// (0, -32, 32) on its side y = -32) and W2; a shelf at z = 32 (facing up) from M to (0, 16, 32)
// and out to x = 32. Its side along x = 0 ends inside W2 and crosses W1 and W2 where no side of
// theirs runs: it shares its stretch on each with that wall half, a valley.
TEST(BrushEdgeTableTest, SideEndingInsideAFaceSharesEachStretchWithTheFaceItCrosses) {
    PolygonBrush brush;
    const uint32_t a = brush.vertex({0, -32, 0}), b = brush.vertex({0, 0, 0}),
                   c = brush.vertex({0, 32, 0}), d = brush.vertex({0, 32, 64}),
                   e = brush.vertex({0, 0, 64}), f = brush.vertex({0, -32, 64}),
                   m = brush.vertex({0, -32, 32});
    const uint32_t s1 = brush.vertex({0, 16, 32}), s2 = brush.vertex({32, 16, 32}),
                   s3 = brush.vertex({32, -32, 32});
    const uint32_t w1 = brush.add_polygon({a, b, e, f, m}, {1, 0, 0});
    const uint32_t w2 = brush.add_polygon({b, c, d, e}, {1, 0, 0});
    const uint32_t shelf = brush.add_polygon({m, s1, s2, s3}, {0, 0, 1});
    const BrushEdgeTable table = build_table(brush.build());
    const BrushEdgeStats& stats = table.stats();
    EXPECT_EQ(stats.half_edges, 13u);
    EXPECT_EQ(stats.shared_edges, 1u);  // W1-W2
    EXPECT_EQ(stats.t_junction_edges, 0u);
    EXPECT_EQ(stats.inside_face_edges, 2u);
    EXPECT_EQ(stats.boundary_edges, 10u);  // W1: 4, W2: 3, the shelf: 3
    EXPECT_EQ(stats.edges, 13u);
    const struct {
        glm::vec3 from, to;
        uint32_t wall;
    } expected[] = {{{0, -32, 32}, {0, 0, 32}, w1}, {{0, 0, 32}, {0, 16, 32}, w2}};
    for (const auto& x : expected) {
        const BrushEdge* edge = find_edge(table, x.from, x.to);
        ASSERT_NE(edge, nullptr) << x.wall;
        EXPECT_EQ(edge->face0, x.wall);
        EXPECT_EQ(edge->face1, shelf);
        EXPECT_NEAR(edge->dihedral_degrees, -90.0f, kAngleTolerance);
        // The wall's half meets the shelf walking the line against the shelf's outline (-y).
        EXPECT_GT(edge->v1.y, edge->v0.y);
        ASSERT_EQ(table.shared_edges_of(x.wall).size(), 2u);  // W1-W2 and this one
    }
    EXPECT_EQ(table.shared_edges_of(shelf).size(), 2u);
}

// The same wall split at z = 32 instead, and the shelf's side along the split: the wall halves'
// sides pair with each other by vertex ids; the shelf meets neither half's inside, and its side
// is left without a partner (three faces on one line).
TEST(BrushEdgeTableTest, SideAlongASplitOfAFaceIsNotInsideIt) {
    PolygonBrush brush;
    const uint32_t a = brush.vertex({0, -32, 0}), c = brush.vertex({0, 32, 0}),
                   d = brush.vertex({0, 32, 64}), f = brush.vertex({0, -32, 64}),
                   m = brush.vertex({0, -32, 32}), n = brush.vertex({0, 32, 32});
    const uint32_t s1 = brush.vertex({0, 16, 32}), s2 = brush.vertex({32, 16, 32}),
                   s3 = brush.vertex({32, -32, 32});
    brush.add_polygon({a, c, n, m}, {1, 0, 0});
    brush.add_polygon({m, n, d, f}, {1, 0, 0});
    const uint32_t shelf = brush.add_polygon({m, s1, s2, s3}, {0, 0, 1});
    const BrushEdgeTable table = build_table(brush.build());
    EXPECT_EQ(table.stats().shared_edges, 1u);
    EXPECT_EQ(table.stats().t_junction_edges, 0u);
    EXPECT_EQ(table.stats().inside_face_edges, 0u);
    EXPECT_EQ(table.shared_edges_of(shelf).size(), 0u);
    const BrushEdge* side = find_edge(table, {0, -32, 32}, {0, 16, 32});
    ASSERT_NE(side, nullptr);
    EXPECT_TRUE(side->is_boundary());
}

// Two floor quads side by side with no vertex in common (as a door beside its frame: compilers
// number each model's vertices apart): their touching sides stay boundary edges.
TEST(BrushEdgeTableTest, PiecesWithoutCommonVerticesDoNotJoin) {
    PolygonBrush brush;
    for (float x0 : {0.0f, 32.0f}) {
        brush.add_polygon({brush.vertex({x0, 0, 0}), brush.vertex({x0 + 32, 0, 0}),
                           brush.vertex({x0 + 32, 32, 0}), brush.vertex({x0, 32, 0})},
                          {0, 0, 1});
    }
    const BrushEdgeTable table = build_table(brush.build());
    EXPECT_EQ(table.stats().t_junction_edges, 0u);
    EXPECT_EQ(table.stats().boundary_edges, 8u);
}

TEST(BrushEdgeTableTest, SkySurfacesOwnNoEdges) {
    PolygonBrush brush;
    add_box(brush, glm::vec3(-64.0f), glm::vec3(64.0f), true);
    brush.set_flags(1, NQR_SURFACE_SKY);  // the ceiling: its sides become the walls' boundaries
    const BrushEdgeTable table = build_table(brush.build());
    EXPECT_EQ(table.stats().surfaces, 5u);
    EXPECT_EQ(table.stats().shared_edges, 8u);
    EXPECT_EQ(table.stats().boundary_edges, 4u);
    for (const BrushEdge& e : table.edges()) {
        EXPECT_NE(e.face0, 1u);
        EXPECT_NE(e.face1, 1u);
    }
}

// Two boxes as two models (as a door beside the world): each model's surface range maps to the
// range of edges it owns.
TEST(BrushEdgeTableTest, SurfaceRangesSelectTheirModelsEdges) {
    PolygonBrush brush;
    add_box(brush, glm::vec3(-16.0f), glm::vec3(16.0f), false);
    add_box(brush, glm::vec3(32.0f), glm::vec3(64.0f), false);
    const BrushEdgeTable table = build_table(brush.build());
    ASSERT_EQ(table.edges().size(), 24u);
    for (const uint32_t first : {0u, 6u}) {
        const uint32_t begin = table.range_begin(first), end = table.range_end(first, 6);
        EXPECT_EQ(end - begin, 12u);
        for (uint32_t e = begin; e < end; ++e) {
            EXPECT_GE(table.edges()[e].face0, first);
            EXPECT_LT(table.edges()[e].face1, first + 6);
        }
    }
    EXPECT_EQ(table.range_end(0, 100), 24u);  // ranges are clamped to the model
    EXPECT_EQ(table.range_begin(100), 24u);
}

// ------------------------------------------------------------------ adjacency, real maps

struct LoadedMap {
    std::string name;
    std::shared_ptr<const nq::BrushModelData> data;
};

LoadedMap load_map(const std::string& path) {
    auto bytes = nq::read_file(path);
    if (!bytes) throw std::runtime_error("cannot read " + path);
    auto bsp = nq::parse_bsp(*bytes, path);
    if (!bsp) throw std::runtime_error("cannot parse " + path);
    return {std::filesystem::path(path).filename().string(),
            nq::BrushModelData::build(std::move(*bsp))};
}

bool is_sky(const nqr_brush_model& brush, const nqr_surface& s) {
    if (s.flags & NQR_SURFACE_SKY) return true;
    return s.texture >= 0 && static_cast<uint32_t>(s.texture) < brush.num_textures &&
           (brush.textures[s.texture].flags & NQR_TEXTURE_SKY);
}

std::vector<glm::vec3> surface_outline(const nqr_brush_model& brush, uint32_t surface) {
    const nqr_surface& s = brush.surfaces[surface];
    std::vector<glm::vec3> outline;
    for (uint32_t i = 0; i < s.num_vertices; ++i) {
        outline.push_back(glm::make_vec3(brush.positions + (s.first_vertex + i) * 3));
    }
    return outline;
}

// Polygon sides that make edges: distinct vertex ids, some length.
uint32_t count_sides(const nqr_brush_model& brush, uint32_t surface, float* perimeter) {
    const nqr_surface& s = brush.surfaces[surface];
    const std::vector<glm::vec3> outline = surface_outline(brush, surface);
    uint32_t sides = 0;
    for (uint32_t i = 0; i < s.num_vertices; ++i) {
        const uint32_t j = (i + 1) % s.num_vertices;
        const float length = glm::length(outline[j] - outline[i]);
        if (brush.vertex_ids[s.first_vertex + i] == brush.vertex_ids[s.first_vertex + j] ||
            length <= 0.1f) {
            continue;
        }
        ++sides;
        *perimeter += length;
    }
    return sides;
}

// Which model (0 = world) each surface belongs to.
std::vector<uint32_t> model_of_surfaces(const nq::Bsp& bsp) {
    std::vector<uint32_t> model(bsp.faces.size(), 0);
    for (uint32_t m = 0; m < bsp.models.size(); ++m) {
        for (uint32_t f = 0; f < bsp.models[m].num_faces; ++f) {
            model[bsp.models[m].first_face + f] = m;
        }
    }
    return model;
}

// Which connected piece each surface belongs to: surfaces that own edges (not sky) joined
// through shared vertex ids.
std::vector<uint32_t> piece_of_surfaces(const nqr_brush_model& brush) {
    if (brush.num_vertices == 0) return std::vector<uint32_t>(brush.num_surfaces, 0);
    std::vector<uint32_t> parent(
        *std::max_element(brush.vertex_ids, brush.vertex_ids + brush.num_vertices) + 1);
    std::iota(parent.begin(), parent.end(), 0u);
    const auto root = [&](uint32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    };
    for (uint32_t s = 0; s < brush.num_surfaces; ++s) {
        const nqr_surface& surface = brush.surfaces[s];
        if (is_sky(brush, surface)) continue;
        for (uint32_t i = 1; i < surface.num_vertices; ++i) {
            parent[root(brush.vertex_ids[surface.first_vertex + i])] =
                root(brush.vertex_ids[surface.first_vertex]);
        }
    }
    std::vector<uint32_t> piece(brush.num_surfaces);
    for (uint32_t s = 0; s < brush.num_surfaces; ++s) {
        piece[s] = root(brush.vertex_ids[brush.surfaces[s].first_vertex]);
    }
    return piece;
}

// A map's surfaces as this file sees them, with a coarse grid to find the ones near a point.
class MapSurfaces {
  public:
    struct Surface {
        std::vector<glm::vec3> outline;
        glm::vec3 normal{0.0f}, centroid{0.0f}, lo{0.0f}, hi{0.0f};
        float dist = 0.0f;
        uint32_t model = 0, piece = 0;
        bool sky = false;
    };

    MapSurfaces(const nqr_brush_model& brush, const nq::Bsp& bsp) {
        const std::vector<uint32_t> model = model_of_surfaces(bsp);
        const std::vector<uint32_t> piece = piece_of_surfaces(brush);
        for (uint32_t s = 0; s < brush.num_surfaces; ++s) {
            Surface out;
            out.outline = surface_outline(brush, s);
            out.normal = glm::make_vec3(brush.surfaces[s].normal);  // the map's plane
            out.dist = brush.surfaces[s].dist;
            out.lo = out.hi = out.outline[0];
            for (const glm::vec3& p : out.outline) {
                out.centroid += p / static_cast<float>(out.outline.size());
                out.lo = glm::min(out.lo, p);
                out.hi = glm::max(out.hi, p);
            }
            out.model = model[s];
            out.piece = piece[s];
            out.sky = is_sky(brush, brush.surfaces[s]);
            const glm::ivec3 first = cell(out.lo - kPointTolerance);
            const glm::ivec3 last = cell(out.hi + kPointTolerance);
            for (int x = first.x; x <= last.x; ++x) {
                for (int y = first.y; y <= last.y; ++y) {
                    for (int z = first.z; z <= last.z; ++z) grid_[key({x, y, z})].push_back(s);
                }
            }
            surfaces_.push_back(std::move(out));
        }
    }

    const Surface& operator[](uint32_t s) const { return surfaces_[s]; }

    // Surfaces whose box, grown by the tolerance, may hold p.
    const std::vector<uint32_t>& near(glm::vec3 p) const {
        static const std::vector<uint32_t> kNone;
        const auto found = grid_.find(key(cell(p)));
        return found == grid_.end() ? kNone : found->second;
    }

  private:
    static constexpr float kCell = 128.0f;
    static glm::ivec3 cell(glm::vec3 p) { return glm::ivec3(glm::floor(p / kCell)); }
    static uint64_t key(glm::ivec3 c) {
        return (uint64_t(uint32_t(c.x) & 0xfffff) << 40) |
               (uint64_t(uint32_t(c.y) & 0xfffff) << 20) | uint64_t(uint32_t(c.z) & 0xfffff);
    }

    std::vector<Surface> surfaces_;
    std::unordered_map<uint64_t, std::vector<uint32_t>> grid_;
};

// Whether p lies in the surface's polygon (its plane and inside its sides, within the tolerance).
bool in_polygon(const MapSurfaces::Surface& s, glm::vec3 p) {
    if (std::abs(glm::dot(s.normal, p) - s.dist) > kPointTolerance) return false;
    for (size_t i = 0; i < s.outline.size(); ++i) {
        const glm::vec3 a = s.outline[i], b = s.outline[(i + 1) % s.outline.size()];
        const glm::vec3 across = glm::cross(s.normal, b - a);  // into the polygon (CCW)
        if (glm::length(across) <= 1e-4f) continue;
        if (glm::dot(p - a, glm::normalize(across)) < -kPointTolerance) return false;
    }
    return true;
}

// The segment runs along the surface's outline, or across its polygon.
bool holds_segment(const MapSurfaces::Surface& s, glm::vec3 p, glm::vec3 q) {
    const glm::vec3 mid = (p + q) * 0.5f;
    if (on_outline(s.outline, p) && on_outline(s.outline, q) && on_outline(s.outline, mid)) {
        return true;
    }
    return in_polygon(s, p) && in_polygon(s, q);
}

// Why a boundary edge of the world or a brush entity has one face only, from the map's own data
// at the edge's midpoint (surfaces hold a point when it lies on their outline or inside their
// polygon; a piece is what shares vertex ids), in this order:
//   sky          a sky surface (which owns no edges) holds it;
//   several      another face of its piece has a side along it in its direction, and the sides
//                along it in that direction outnumber those against it (several faces meet
//                there: a wall with faces into water and into air, say): one is left without a
//                partner whatever the pairing;
//   other_piece  a surface of another model (a door, a trigger) or of another piece of its
//                model (a detail sharing no vertex with it) holds it: pieces never join;
//   buried       the space in front of its face next to it is solid (hull 0 point contents);
//   nothing      no other surface of its model holds it: the map has no face there;
//   unexplained  none of these, or a face of its piece has it inside (not along a side, not in
//                the edge's own plane): a partner the matcher should have found.
enum class OpenReason { sky, several, other_piece, buried, nothing, unexplained };

OpenReason why_open(const MapSurfaces& map, const nq::Bsp& bsp, const BrushEdge& edge) {
    const glm::vec3 mid = (edge.v0 + edge.v1) * 0.5f;
    const glm::vec3 along = glm::normalize(edge.v1 - edge.v0);
    const MapSurfaces::Surface& owner = map[edge.face0];
    bool sky = false, other_piece = false, same_model = false, inside_own_piece = false;
    int one_way = 1, other_way = 0;  // its own side runs one way
    for (const uint32_t s : map.near(mid)) {
        const MapSurfaces::Surface& surface = map[s];
        if (s == edge.face0) continue;
        const bool on_side = on_outline(surface.outline, mid);
        if (!on_side && !in_polygon(surface, mid)) continue;
        const bool same_piece = surface.model == owner.model && surface.piece == owner.piece;
        sky |= surface.sky;
        other_piece |= !surface.sky && !same_piece;
        same_model |= !surface.sky && surface.model == owner.model;
        if (surface.sky || !same_piece) continue;
        inside_own_piece |=
            !on_side && glm::length(glm::cross(surface.normal, owner.normal)) > 1e-3f;
        for (size_t i = 0; i < surface.outline.size(); ++i) {
            const glm::vec3 a = surface.outline[i];
            const glm::vec3 b = surface.outline[(i + 1) % surface.outline.size()];
            if (glm::length(b - a) <= 0.1f || distance_to_segment(mid, a, b) > kPointTolerance) {
                continue;
            }
            const float cosine = glm::dot(glm::normalize(b - a), along);
            if (cosine > 0.9999f) ++one_way;
            if (cosine < -0.9999f) ++other_way;
        }
    }
    if (inside_own_piece) return OpenReason::unexplained;
    if (sky) return OpenReason::sky;
    if (one_way > 1 && one_way > other_way) return OpenReason::several;
    if (other_piece) return OpenReason::other_piece;
    const glm::vec3 into = glm::cross(owner.normal, along);  // into the face (CCW)
    const glm::vec3 in_front = mid + owner.normal + into;
    if (nq::point_contents(bsp, 0, {in_front.x, in_front.y, in_front.z}, owner.model) ==
        nq::bsp_contents::solid) {
        return OpenReason::buried;
    }
    return same_model ? OpenReason::unexplained : OpenReason::nothing;
}

void check_map_invariants(const LoadedMap& map, double* shared_share) {
    SCOPED_TRACE(map.name);
    const nqr_brush_model& brush = map.data->abi();
    const auto start = std::chrono::steady_clock::now();
    const BrushEdgeTable table = build_table(brush);
    const double build_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    const BrushEdgeStats& stats = table.stats();

    uint32_t sides = 0, owners = 0;
    std::vector<float> perimeter(brush.num_surfaces, 0.0f);
    for (uint32_t s = 0; s < brush.num_surfaces; ++s) {
        if (is_sky(brush, brush.surfaces[s])) continue;
        ++owners;
        sides += count_sides(brush, s, &perimeter[s]);
    }
    EXPECT_EQ(stats.surfaces, owners);
    EXPECT_EQ(stats.half_edges, sides);
    EXPECT_EQ(2 * stats.shared_edges + stats.unmatched_half_edges, stats.half_edges);
    EXPECT_EQ(stats.shared_edges + stats.t_junction_edges + stats.inside_face_edges +
                  stats.boundary_edges,
              stats.edges);
    ASSERT_EQ(table.edges().size(), stats.edges);

    // Each edge lies on the outline of one of its faces, within one model; the other face holds
    // it on its outline too, or across its polygon (a side ending on the inside of a face).
    // Together the edges on a surface's outline cover it once. The dihedral angle is the angle
    // between the faces' normals, a valley where each face lies in front of the other's plane.
    const MapSurfaces surfaces(brush, map.data->bsp());
    std::vector<float> covered(brush.num_surfaces, 0.0f);
    int off_faces = 0, across_models = 0, inside = 0, wrong_angle = 0, wrong_sign = 0;
    for (const BrushEdge& e : table.edges()) {
        const float length = glm::length(e.v1 - e.v0);
        const glm::vec3 mid = (e.v0 + e.v1) * 0.5f;
        uint32_t on_outline_of = technical::kNoFace;
        for (uint32_t face : {e.face1, e.face0}) {
            if (face == technical::kNoFace) continue;
            const MapSurfaces::Surface& s = surfaces[face];
            if (on_outline(s.outline, e.v0) && on_outline(s.outline, e.v1) &&
                on_outline(s.outline, mid)) {
                covered[face] += length;
                on_outline_of = face;
            }
        }
        EXPECT_LE(std::abs(e.dihedral_degrees), 180.0f);
        if (on_outline_of == technical::kNoFace) {
            ++off_faces;
            continue;
        }
        if (e.is_boundary()) continue;
        const uint32_t other = on_outline_of == e.face0 ? e.face1 : e.face0;
        const MapSurfaces::Surface& side = surfaces[on_outline_of];
        const MapSurfaces::Surface& across = surfaces[other];
        if (!on_outline(across.outline, mid)) {
            ++inside;
            if (!holds_segment(across, e.v0, e.v1)) ++off_faces;
        }
        if (side.model != across.model) ++across_models;
        const float between =
            glm::degrees(std::acos(std::clamp(glm::dot(side.normal, across.normal), -1.0f, 1.0f)));
        if (std::abs(std::abs(e.dihedral_degrees) - between) > 0.1f) ++wrong_angle;
        const float height = glm::dot(across.normal, side.centroid) - across.dist;
        if (std::abs(e.dihedral_degrees) > 1.0f && std::abs(e.dihedral_degrees) < 179.0f &&
            std::abs(height) > 0.01f && (e.dihedral_degrees < 0.0f) != (height > 0.0f)) {
            ++wrong_sign;
        }
    }
    EXPECT_EQ(off_faces, 0);
    EXPECT_EQ(across_models, 0);
    EXPECT_EQ(inside, static_cast<int>(stats.inside_face_edges));
    EXPECT_EQ(wrong_angle, 0);
    EXPECT_EQ(wrong_sign, 0);
    int badly_covered = 0;
    for (uint32_t s = 0; s < brush.num_surfaces; ++s) {
        if (std::abs(covered[s] - perimeter[s]) > 0.5f) ++badly_covered;
    }
    EXPECT_EQ(badly_covered, 0);

    // Every boundary edge is open for a reason the map's data shows.
    std::array<int, 6> open{};
    for (const BrushEdge& e : table.edges()) {
        if (!e.is_boundary()) continue;
        ++open[static_cast<size_t>(why_open(surfaces, map.data->bsp(), e))];
    }
    EXPECT_EQ(open[static_cast<size_t>(OpenReason::unexplained)], 0);

    *shared_share = static_cast<double>(stats.edges - stats.boundary_edges) /
                    std::max<uint32_t>(stats.edges, 1);
    std::cout << "[ brush edges ] " << map.name << ": surfaces " << stats.surfaces
              << ", half-edges " << stats.half_edges << ", edges " << stats.edges << " (shared "
              << stats.shared_edges << ", T-junction " << stats.t_junction_edges
              << ", inside a face " << stats.inside_face_edges << ", boundary "
              << stats.boundary_edges << ": sky " << open[0] << ", several faces " << open[1]
              << ", other piece " << open[2] << ", buried " << open[3] << ", nothing there "
              << open[4] << ", unexplained " << open[5] << "), creases " << stats.creases
              << ", shared share " << *shared_share << ", built in " << build_ms << " ms\n";
}

TEST(BrushEdgeRealDataTest, EveryMapKeepsTheInvariantsAndStartIsMostlyShared) {
    int maps = 0;
    for (const std::string& path : nq::test::lq1_files("maps", ".bsp")) {
        double shared_share = 0.0;
        check_map_invariants(load_map(path), &shared_share);
        if (std::filesystem::path(path).filename() == "start.bsp") {
            EXPECT_GT(shared_share, 0.9);
        }
        ++maps;
    }
    EXPECT_GE(maps, 3);
}

// ------------------------------------------------------------------ drawing

// Flat grey faces for the edges to be depth-tested against (test-only shader).
class FaceDrawer {
  public:
    static constexpr Rgb kFaceGrey{128, 128, 128};

    explicit FaceDrawer(const PolygonBrush& brush) {
        static const char* kVertex = R"(#version 330 core
layout(location = 0) in vec3 a_position;
uniform mat4 u_mvp;
void main() { gl_Position = u_mvp * vec4(a_position, 1.0); })";
        static const char* kFragment = R"(#version 330 core
out vec4 o_color;
void main() { o_color = vec4(128.0 / 255.0, 128.0 / 255.0, 128.0 / 255.0, 1.0); })";
        gl::ProgramBuild build = gl::Program::build({"test faces", kVertex, kFragment}, nullptr);
        EXPECT_TRUE(build.ok()) << build.error;
        program_ = std::move(build.program);
        std::vector<glm::vec3> triangles;
        for (uint32_t s = 0; s < brush.num_polygons(); ++s) {
            const std::vector<glm::vec3> outline = brush.outline(s);
            for (size_t i = 1; i + 1 < outline.size(); ++i) {
                triangles.insert(triangles.end(), {outline[0], outline[i], outline[i + 1]});
            }
        }
        count_ = static_cast<GLsizei>(triangles.size());
        vertex_array_ = gl::VertexArray::create(nullptr);
        buffer_ = gl::Buffer::create(nullptr);
        glBindVertexArray(vertex_array_.id());
        glBindBuffer(GL_ARRAY_BUFFER, buffer_.id());
        glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(triangles.size() * sizeof(glm::vec3)),
                     triangles.data(), GL_STATIC_DRAW);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
        glBindVertexArray(0);
        glBindBuffer(GL_ARRAY_BUFFER, 0);
    }

    void draw(const glm::mat4& mvp) {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LEQUAL);
        program_.use();
        glUniformMatrix4fv(program_.location("u_mvp"), 1, GL_FALSE, glm::value_ptr(mvp));
        glBindVertexArray(vertex_array_.id());
        glDrawArrays(GL_TRIANGLES, 0, count_);
        glBindVertexArray(0);
        glUseProgram(0);
    }

  private:
    gl::Program program_;
    gl::VertexArray vertex_array_;
    gl::Buffer buffer_;
    GLsizei count_ = 0;
};

constexpr Rgb kSilhouetteRed{255, 0, 0}, kRidgeGreen{0, 255, 0}, kValleyBlue{0, 0, 255};

EdgeSettings base_colour_settings() {
    EdgeSettings s;
    s.color_mode = EdgeColorMode::base;
    s.distance_fade = false;
    s.silhouette_color = {1, 0, 0};
    s.ridge_color = {0, 1, 0};
    s.valley_color = {0, 0, 1};
    s.silhouette_width = s.ridge_width = s.valley_width = 9.0f;  // 2.4 pixels at 128 lines
    return s;
}

EdgeFrameUniforms frame_uniforms(const nqr_camera& camera) {
    EdgeFrameUniforms u;
    u.projection = glm::make_mat4(camera.projection);
    u.viewport = {static_cast<float>(kSize), static_cast<float>(kSize)};
    u.z_near = camera.z_near;
    return u;
}

// Pitch and yaw (degrees) looking from `eye` at `target`.
glm::vec3 angles_towards(glm::vec3 eye, glm::vec3 target) {
    const glm::vec3 f = glm::normalize(target - eye);
    return {glm::degrees(-std::asin(f.z)), glm::degrees(std::atan2(f.y, f.x)), 0.0f};
}

bool colour_around(const std::vector<Rgb>& pixels, glm::vec2 at, Rgb colour, int tolerance) {
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            const int x = static_cast<int>(at.x) + dx, y = static_cast<int>(at.y) + dy;
            if (x < 0 || y < 0 || x >= kSize || y >= kSize) continue;
            if (near(pixels[y * kSize + x], colour, tolerance)) return true;
        }
    }
    return false;
}

int count_near(const std::vector<Rgb>& pixels, Rgb colour, int tolerance) {
    return static_cast<int>(std::count_if(
        pixels.begin(), pixels.end(), [&](const Rgb& p) { return near(p, colour, tolerance); }));
}

class BrushEdgeDrawTest : public GlSuiteTest<BrushEdgeDrawTest> {
  protected:
    void SetUp() override {
        GlSuiteTest::SetUp();
        if (HasFatalFailure()) return;
        std::string error;
        ASSERT_TRUE(drawer_.init(&tracker_, error)) << error;
    }

    void TearDown() override {
        drawer_.reset();
        mesh_.reset();
        EXPECT_EQ(tracker_.total_live(), 0);
        EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    }

    void make_mesh(const nqr_brush_model& brush) {
        std::string error;
        mesh_ = BrushEdgeMesh::create(&tracker_, brush, error, palette_.data());
        ASSERT_NE(mesh_, nullptr) << error;
    }

    gl::ObjectTracker tracker_;
    std::array<uint8_t, 768> palette_ = make_test_palette();
    BrushEdgeDrawer drawer_;
    std::unique_ptr<BrushEdgeMesh> mesh_;
};

// The box at the origin of its model space, placed at `kBoxPlace`; the eye above one corner.
const glm::vec3 kBoxPlace(100.0f, 20.0f, 0.0f);
const glm::vec3 kBoxEye = kBoxPlace + glm::vec3(45.0f, 35.0f, 40.0f);
constexpr float kBoxHalf = 16.0f;

struct BoxScene {
    PolygonBrush brush;
    nqr_camera camera;
    nqr_entity entity;
    npr::FrameView view;

    explicit BoxScene(PolygonBrush textured = PolygonBrush()) : brush(std::move(textured)) {
        add_box(brush, glm::vec3(-kBoxHalf), glm::vec3(kBoxHalf), false);
        camera = make_camera(kBoxEye, angles_towards(kBoxEye, kBoxPlace), 60.0f);
        entity = make_entity(1, glm::translate(glm::mat4(1.0f), kBoxPlace));
        const glm::vec3 eye_model = kBoxEye - kBoxPlace;
        std::copy_n(glm::value_ptr(eye_model), 3, entity.eye_model);
        TestFrame frame;
        npr::read_frame_view(frame.build(camera, 0), view);
    }

    glm::mat4 mvp() const {
        return glm::make_mat4(camera.view_projection) * glm::make_mat4(entity.model_matrix);
    }
};

TEST_F(BrushEdgeDrawTest, BoxFromOutsideShowsRidgesAndOutlineButNotItsHiddenEdges) {
    BoxScene scene;
    make_mesh(scene.brush.build());
    FaceDrawer faces(scene.brush);
    gl_->clear();
    faces.draw(scene.mvp());
    drawer_.draw_entity(scene.view, frame_uniforms(scene.camera), scene.entity, *mesh_, 0, 6,
                        base_colour_settings());
    const std::vector<Rgb> pixels = gl_->pixels();
    gl_->dump_if_requested("brush_edges_box");

    int ridges = 0, silhouettes = 0, hidden = 0;
    const glm::vec3 eye_model = kBoxEye - kBoxPlace;
    const glm::vec3 lo(-kBoxHalf), hi(kBoxHalf);
    for (const BoxEdge& edge : box_edges()) {
        const glm::vec3 p = box_corner(lo, hi, edge.a), q = box_corner(lo, hi, edge.b);
        bool front[2];
        for (int k = 0; k < 2; ++k) {
            const glm::vec3 n = kBoxFaces[edge.faces[k]].outward;
            front[k] = glm::dot(n, eye_model - p) > 0.0f;  // p lies on both faces
        }
        const glm::vec2 at = project(scene.camera, kBoxPlace + (p + q) * 0.5f);
        SCOPED_TRACE(testing::Message()
                     << "edge " << edge.a << "-" << edge.b << " at " << at.x << ", " << at.y);
        if (front[0] && front[1]) {
            EXPECT_TRUE(colour_around(pixels, at, kRidgeGreen, 40));
            ++ridges;
        } else if (front[0] != front[1]) {
            EXPECT_TRUE(colour_around(pixels, at, kSilhouetteRed, 40));
            ++silhouettes;
        } else {
            EXPECT_FALSE(colour_around(pixels, at, kRidgeGreen, 60));
            EXPECT_FALSE(colour_around(pixels, at, kSilhouetteRed, 60));
            EXPECT_FALSE(colour_around(pixels, at, kValleyBlue, 60));
            EXPECT_TRUE(near(pixels[static_cast<int>(at.y) * kSize + static_cast<int>(at.x)],
                             FaceDrawer::kFaceGrey, 2));
            ++hidden;
        }
    }
    EXPECT_EQ(ridges, 3);
    EXPECT_EQ(silhouettes, 6);
    EXPECT_EQ(hidden, 3);
    EXPECT_EQ(count_near(pixels, kValleyBlue, 60), 0);
}

// Silhouettes only, then creases only: each switch removes its kind.
TEST_F(BrushEdgeDrawTest, SwitchesTurnSilhouettesAndCreasesOff) {
    BoxScene scene;
    make_mesh(scene.brush.build());
    EdgeSettings settings = base_colour_settings();
    settings.creases = false;
    gl_->clear();
    drawer_.draw_entity(scene.view, frame_uniforms(scene.camera), scene.entity, *mesh_, 0, 6,
                        settings);
    std::vector<Rgb> pixels = gl_->pixels();
    EXPECT_GT(count_near(pixels, kSilhouetteRed, 40), 50);
    EXPECT_EQ(count_near(pixels, kRidgeGreen, 60), 0);

    settings.creases = true;
    settings.silhouettes = false;
    gl_->clear();
    drawer_.draw_entity(scene.view, frame_uniforms(scene.camera), scene.entity, *mesh_, 0, 6,
                        settings);
    pixels = gl_->pixels();
    EXPECT_EQ(count_near(pixels, kSilhouetteRed, 60), 0);
    EXPECT_GT(count_near(pixels, kRidgeGreen, 40), 20);

    settings.crease_angle_degrees = 95.0f;  // the box bends by 90: no creases left
    gl_->clear();
    drawer_.draw_entity(scene.view, frame_uniforms(scene.camera), scene.entity, *mesh_, 0, 6,
                        settings);
    EXPECT_EQ(count_near(gl_->pixels(), kRidgeGreen, 60), 0);
}

// White addition on ridges: the texture's average over its smallest mip (2 x 2: one red, three
// blue texels; mip 0 is all red) plus w.
TEST_F(BrushEdgeDrawTest, RidgeColourIsTheSmallestMipsAverageWithWhiteAdded) {
    BoxScene scene(
        PolygonBrush(colour::kRed, {colour::kRed, colour::kBlue, colour::kBlue, colour::kBlue}));
    make_mesh(scene.brush.build());
    EdgeSettings settings = base_colour_settings();
    settings.color_mode = EdgeColorMode::white_creases;
    settings.white_w = 0.4f;
    gl_->clear();
    drawer_.draw_entity(scene.view, frame_uniforms(scene.camera), scene.entity, *mesh_, 0, 6,
                        settings);
    const Rgb red = palette_colour(palette_, colour::kRed);
    const Rgb blue = palette_colour(palette_, colour::kBlue);
    const auto whitened = [](double channel) {
        return static_cast<int>(std::lround(std::min(255.0, channel + 0.4 * 255.0)));
    };
    const Rgb expected{whitened((red.r + 3.0 * blue.r) / 4.0),
                       whitened((red.g + 3.0 * blue.g) / 4.0),
                       whitened((red.b + 3.0 * blue.b) / 4.0)};
    // The ridge from the corner nearest the eye (+x+y+z) along -x.
    const glm::vec3 p(kBoxHalf), q(-kBoxHalf, kBoxHalf, kBoxHalf);
    const glm::vec2 at = project(scene.camera, kBoxPlace + (p + q) * 0.5f);
    EXPECT_TRUE(colour_around(gl_->pixels(), at, expected, 3)) << "expected " << expected;
}

TEST_F(BrushEdgeDrawTest, RoomSeenFromInsideHasValleyCornersOnly) {
    PolygonBrush brush;
    const float half = 64.0f;
    add_box(brush, glm::vec3(-half), glm::vec3(half), true);
    make_mesh(brush.build());
    FaceDrawer faces(brush);
    const glm::vec3 eye(-20.0f, -10.0f, -5.0f), corner(half);
    const nqr_camera camera = make_camera(eye, angles_towards(eye, corner), 90.0f);
    TestFrame frame;
    frame.use_visible_list = true;
    frame.visible = {0, 1, 2, 3, 4, 5};
    const nqr_frame* built = frame.build(camera, 1);
    npr::FrameView view;
    ASSERT_TRUE(npr::read_frame_view(built, view));
    gl_->clear();
    faces.draw(glm::make_mat4(camera.view_projection));
    drawer_.draw_world(view, frame_uniforms(camera), *built, *mesh_, base_colour_settings());
    const std::vector<Rgb> pixels = gl_->pixels();
    gl_->dump_if_requested("brush_edges_room");

    int checked = 0;
    for (int axis = 0; axis < 3; ++axis) {
        for (float along : {12.0f, 24.0f, 40.0f}) {
            glm::vec3 point = corner;
            point[axis] -= along;
            const glm::vec2 at = project(camera, point);
            if (at.x < 3 || at.y < 3 || at.x > kSize - 4 || at.y > kSize - 4) continue;
            EXPECT_TRUE(colour_around(pixels, at, kValleyBlue, 40)) << axis << " " << along;
            ++checked;
        }
    }
    EXPECT_GE(checked, 6);
    EXPECT_EQ(count_near(pixels, kSilhouetteRed, 60), 0);
    EXPECT_EQ(count_near(pixels, kRidgeGreen, 60), 0);
}

// The per-frame list names each edge of the listed surfaces once, whatever the repeats, and
// skips surface indices the model does not have.
TEST_F(BrushEdgeDrawTest, WorldListNamesEachVisibleEdgeOnce) {
    PolygonBrush brush;
    add_box(brush, glm::vec3(-16.0f), glm::vec3(16.0f), false);
    make_mesh(brush.build());
    const std::vector<uint32_t> all = {0, 1, 2, 3, 4, 5, 5, 0};
    std::span<const uint32_t> lines = mesh_->line_indices_of(all);
    EXPECT_EQ(lines.size(), 24u);
    std::vector<uint32_t> sorted(lines.begin(), lines.end());
    std::sort(sorted.begin(), sorted.end());
    for (uint32_t i = 0; i < sorted.size(); ++i) EXPECT_EQ(sorted[i], i);
    // Bottom (0) and top (1) share no edge: 4 + 4 edges; 99 is no surface.
    const std::vector<uint32_t> two = {0, 1, 99, 1};
    lines = mesh_->line_indices_of(two);
    EXPECT_EQ(lines.size(), 16u);
    for (size_t i = 0; i < lines.size(); i += 2) {
        EXPECT_EQ(lines[i] % 2, 0u);
        EXPECT_EQ(lines[i + 1], lines[i] + 1);
        const BrushEdge& edge = mesh_->table().edges()[lines[i] / 2];
        EXPECT_TRUE(edge.face0 <= 1 || edge.face1 <= 1);
    }
}

// Two floor tiles in one plane (a BSP split) and a wall on one of them: the tiles' shared edge
// can never be a silhouette or a crease and is left out of the list; the wall's is listed.
TEST_F(BrushEdgeDrawTest, WorldListLeavesOutEdgesBetweenFacesOfOnePlane) {
    PolygonBrush brush;
    const uint32_t a = brush.vertex({0, 0, 0}), b = brush.vertex({32, 0, 0});
    const uint32_t c = brush.vertex({32, 32, 0}), d = brush.vertex({0, 32, 0});
    const uint32_t e = brush.vertex({64, 0, 0}), f = brush.vertex({64, 32, 0});
    const uint32_t top_a = brush.vertex({0, 0, 32}), top_d = brush.vertex({0, 32, 32});
    brush.add_polygon({a, b, c, d}, {0, 0, 1});
    brush.add_polygon({b, e, f, c}, {0, 0, 1});
    brush.add_polygon({a, d, top_d, top_a}, {1, 0, 0});
    make_mesh(brush.build());
    ASSERT_EQ(mesh_->stats().shared_edges, 2u);
    const std::vector<uint32_t> all = {0, 1, 2};
    const std::span<const uint32_t> lines = mesh_->line_indices_of(all);
    ASSERT_EQ(lines.size(), 2u);
    const BrushEdge& listed = mesh_->table().edges()[lines[0] / 2];
    EXPECT_NEAR(std::abs(listed.dihedral_degrees), 90.0f, 0.01f);
    // Both edges exist in the table; only the flat one is left out.
    int flat = 0;
    for (const BrushEdge& edge : mesh_->table().edges()) {
        if (!edge.is_boundary() && std::abs(edge.dihedral_degrees) < 0.01f) ++flat;
    }
    EXPECT_EQ(flat, 1);
}

// The world's boundary edges are not drawn; a brush entity's are, as silhouettes, while their
// face looks at the eye. One lone quad seen from the front, then from behind.
TEST_F(BrushEdgeDrawTest, BoundaryEdgesOutlineEntitiesOnly) {
    PolygonBrush brush;
    brush.add_polygon({brush.vertex({0, -16, -16}), brush.vertex({0, 16, -16}),
                       brush.vertex({0, 16, 16}), brush.vertex({0, -16, 16})},
                      {1, 0, 0});
    make_mesh(brush.build());
    ASSERT_EQ(mesh_->stats().boundary_edges, 4u);
    enum class As { entity, world_list, world_all };
    const auto draw = [&](glm::vec3 eye, As as) {
        const nqr_camera camera = make_camera(eye, angles_towards(eye, glm::vec3(0.0f)), 90.0f);
        TestFrame frame;
        frame.use_visible_list = as == As::world_list;
        frame.visible = {0};
        const nqr_frame* built = frame.build(camera, 1);
        npr::FrameView view;
        npr::read_frame_view(built, view);
        nqr_entity entity = make_entity(1);
        std::copy_n(glm::value_ptr(eye), 3, entity.eye_model);
        gl_->clear();
        if (as == As::entity) {
            drawer_.draw_entity(view, frame_uniforms(camera), entity, *mesh_, 0, 1,
                                base_colour_settings());
        } else {
            drawer_.draw_world(view, frame_uniforms(camera), *built, *mesh_,
                               base_colour_settings());
        }
        return count_near(gl_->pixels(), kSilhouetteRed, 40);
    };
    EXPECT_GT(draw({40, 0, 0}, As::entity), 100);
    EXPECT_EQ(draw({-40, 0, 0}, As::entity), 0);
    EXPECT_EQ(draw({40, 0, 0}, As::world_list), 0);
    EXPECT_EQ(draw({40, 0, 0}, As::world_all), 0);
}

// ------------------------------------------------------------------ start.bsp: cost per frame

struct StartView {
    nqr_camera camera;
    std::vector<uint32_t> visible;
};

StartView start_view(const nq::Bsp& bsp, int width, int height) {
    auto entities = nq::parse_entities(bsp.entities, "start.bsp");
    if (!entities) throw std::runtime_error("start.bsp entities");
    const auto starts = nq::find_entities(*entities, "info_player_start");
    if (starts.empty()) throw std::runtime_error("start.bsp has no info_player_start");
    const auto origin = nq::find_vec3(*starts[0], "origin");
    float yaw = 0.0f;
    if (auto angle = nq::find_value(*starts[0], "angle")) yaw = std::stof(std::string(*angle));
    const glm::vec3 eye((*origin)[0], (*origin)[1], (*origin)[2] + 22.0f);
    StartView out;
    out.camera = make_camera(eye, {0.0f, yaw, 0.0f}, 73.7f);  // fov_x 90 at 4:3
    const glm::mat4 projection =
        glm::perspective(glm::radians(73.7f), float(width) / float(height), 4.0f, 4096.0f);
    const glm::mat4 view = glm::make_mat4(out.camera.view);
    const glm::mat4 view_projection = projection * view;
    std::copy_n(glm::value_ptr(projection), 16, out.camera.projection);
    std::copy_n(glm::value_ptr(view_projection), 16, out.camera.view_projection);
    out.camera.z_near = 4.0f;
    out.camera.viewport[2] = width;
    out.camera.viewport[3] = height;
    nq::WorldCuller culler(bsp);
    out.visible.resize(culler.max_visible_surfaces());
    out.visible.resize(
        culler.cull(eye, nq::Frustum::from_view_projection(view_projection), out.visible));
    return out;
}

// A 640 x 480 framebuffer for timing at a playable size.
class TimingTarget {
  public:
    static constexpr int kWidth = 640, kHeight = 480;

    TimingTarget() : framebuffer_(kWidth, kHeight) {}

    // Pixels that are not the clear colour (black).
    int drawn_pixels() const {
        std::vector<uint8_t> rgba(kWidth * kHeight * 4);
        glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
        int count = 0;
        for (size_t i = 0; i < rgba.size(); i += 4)
            count += (rgba[i] | rgba[i + 1] | rgba[i + 2]) != 0;
        return count;
    }

  private:
    SizedFramebuffer framebuffer_;
};

TEST_F(BrushEdgeDrawTest, StartMapWorldEdgesDrawWithoutAllocatingAndReportTheirCost) {
    const LoadedMap map = load_map(nq::test::lq1_dir() + "/maps/start.bsp");
    make_mesh(map.data->abi());
    const StartView start =
        start_view(map.data->bsp(), TimingTarget::kWidth, TimingTarget::kHeight);
    ASSERT_GT(start.visible.size(), 0u);
    TestFrame frame;
    frame.use_visible_list = true;
    frame.visible = start.visible;
    const nqr_frame* built = frame.build(start.camera, 1);
    npr::FrameView view;
    ASSERT_TRUE(npr::read_frame_view(built, view));
    EdgeFrameUniforms uniforms = frame_uniforms(start.camera);
    uniforms.viewport = {float(TimingTarget::kWidth), float(TimingTarget::kHeight)};
    uniforms.z_near = 4.0f;
    const EdgeSettings settings;  // the style's defaults

    TimingTarget target;
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    drawer_.draw_world(view, uniforms, *built, *mesh_, settings);  // warms shader variants
    glFinish();
    EXPECT_GT(target.drawn_pixels(), 500);

    constexpr int kFrames = 20;
    const long allocations_before = ::nq::test::g_allocations.load();
    const auto start_time = std::chrono::steady_clock::now();
    for (int i = 0; i < kFrames; ++i) {
        drawer_.draw_world(view, uniforms, *built, *mesh_, settings);
        glFinish();
    }
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_time)
            .count() /
        kFrames;
    EXPECT_EQ(::nq::test::g_allocations.load(), allocations_before);

    const auto cpu_start = std::chrono::steady_clock::now();
    size_t listed = 0;
    for (int i = 0; i < kFrames; ++i) listed = mesh_->line_indices_of(start.visible).size() / 2;
    const double cpu_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - cpu_start)
            .count() /
        kFrames;
    std::cout << "[ brush edges ] start.bsp from the player start: " << start.visible.size()
              << " visible surfaces, " << listed << " edges listed (" << cpu_ms
              << " ms), draw_world " << ms << " ms per frame at 640x480\n";
    gl_->bind();
}

}  // namespace
}  // namespace nq::npr::test
