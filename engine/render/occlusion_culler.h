// Which entities the world hides completely, decided on the CPU before the frame is drawn.
//
// Each frame the faces the plugin will draw with depth writes (the world's listed ones and
// those of opaque brush entities: front-facing, opaque textures) are rasterised into a 1/w
// buffer at the view's own resolution, sampled at pixel centres as the GPU samples them, but
// only on the pixels some candidate entity's screen rectangle covers. A face fills pixels right
// up to edges it shares with another face drawn in the same placement, and stops short of its
// other edges (1/128 pixel); its depth is taken from its plane pushed back behind every vertex,
// less the change across 1/64 pixel. A candidate is hidden when every pixel of its rectangle
// (or, for one given by its points, of each of its triangles' rectangles) holds a face nearer
// than its nearest point there (with a margin of 1/1000 of the distance plus one unit), so the
// GPU's depth test would reject all of its fragments.
//
// Nothing is allocated per frame: buffers follow the viewport's size and are kept.
#pragma once

#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "nqr_renderer.h"
#include "render/occluder_mesh.h"

namespace nq {

class OcclusionCuller {
  public:
    static constexpr int32_t kNotHideable = -1;
    static constexpr int32_t kOffScreen = -2;  // every point lands outside the viewport

    // Keeps a reference to `mesh`, which must outlive the culler.
    explicit OcclusionCuller(const OccluderMesh& mesh);

    // Starts a frame seen by `camera` (a perspective projection; anything else hides nothing).
    void begin_frame(const nqr_camera& camera);
    // An object whose drawn fragments all lie in the box [mins, maxs] placed by `placement`.
    // Returns its candidate number, kOffScreen (all of it in front of the near plane and
    // beyond one side of the viewport: nothing to draw at all) or kNotHideable (reaching the
    // near plane).
    int32_t add_box(const glm::mat4& placement, const glm::vec3& mins, const glm::vec3& maxs);
    // An object drawn as triangles between `points` (its own space) placed by `placement`:
    // tighter than its box, as the nearest point and the screen bounds are the vertices'.
    int32_t add_points(const glm::mat4& placement, std::span<const glm::vec3> points);
    // Occluders, rasterised where candidates lie; add them after all the candidates. The
    // frame's visible surfaces of the world (placed as they are):
    void rasterize_world(std::span<const uint32_t> visible_surfaces);
    // A whole model of the same map (surfaces [first, first + count)) placed by `placement`,
    // `eye_in_model` being the eye in the model's own space.
    void rasterize_model(uint32_t first, uint32_t count, const glm::mat4& placement,
                         const glm::vec3& eye_in_model);
    // Whether the occluders rasterised so far hide the candidate at every pixel of its
    // rectangle, its nearest point behind them all.
    bool hidden(int32_t candidate) const;
    // The tighter test for a candidate added by add_points: whether its triangle (a, b, c)
    // (indices into its points) is hidden by the same rule, on its own rectangle. An object all
    // of whose triangles are hidden is hidden, though its rectangle may hold farther pixels
    // beside it.
    bool triangle_hidden(int32_t candidate, uint32_t a, uint32_t b, uint32_t c) const;

    // For tests: the stored 1/w at pixel (x, y) (GL window coordinates), 0 where no face was
    // rasterised.
    float inverse_w_at(int x, int y) const;
    uint32_t candidate_count() const { return candidate_count_; }

  private:
    struct Candidate {
        int x0, y0, x1, y1;       // pixel rectangle, inclusive
        float nearest_inverse_w;  // the world must be nearer than this (margin included)
        uint32_t first_point = 0, num_points = 0;  // clip positions kept in points_
    };
    // Where a candidate's points land: NDC bounds and the nearest clip w.
    struct ScreenExtent {
        float nearest_w = INFINITY;
        glm::vec2 lo{INFINITY}, hi{-INFINITY};
        bool crosses_near = false;
        void add(const glm::vec4& clip);
    };
    struct ScreenVertex {
        glm::vec2 p;
        uint32_t key;  // BSP vertex id; kClipKey for a point made by near-plane clipping
    };
    struct EdgeLine {
        float a, b, c;  // a x + b y + c >= t inside
        float t;        // 0 on an edge shared with a face drawn this frame
    };
    static constexpr uint32_t kClipKey = UINT32_MAX;

    int32_t add_candidate(const ScreenExtent& extent);
    // The candidate's rectangle and depth limit; false (with the reason) when it has none.
    bool bound(const ScreenExtent& extent, Candidate& out, int32_t& reason) const;
    bool rectangle_hidden(const Candidate& c) const;
    void resize(int width, int height);
    void begin_occluders();
    void set_placement(const glm::mat4& placement);
    bool stamp_if_drawn(uint32_t surface, const glm::vec3& eye_in_model);
    bool edge_shared(uint32_t vertex) const;
    bool project_face(const OccluderFace& face);
    void make_edge_lines(uint32_t count);
    void fill_face(const OccluderFace& face);
    bool face_depth_plane(const OccluderFace& face, glm::vec3& plane) const;

    const OccluderMesh& mesh_;
    bool perspective_ = false;
    glm::mat4 view_{1.0f}, view_projection_{1.0f};
    glm::mat4 projection_{1.0f};
    glm::vec3 eye_{0.0f};
    int width_ = 0, height_ = 0;
    std::vector<float> inverse_w_;      // width_ x height_, rows bottom up
    std::vector<int> row_lo_, row_hi_;  // per row: pixels [lo, hi] some candidate covers
    int rows_lo_ = 0, rows_hi_ = -1;    // rows with candidates
    std::vector<Candidate> candidates_;
    std::vector<glm::vec4> points_;  // candidates' points in clip space, for triangle tests
    uint32_t point_count_ = 0;
    uint32_t candidate_count_ = 0;
    // Faces drawn in the current placement carry its pass number (a model drawn twice in a
    // frame, by two entities, is two passes).
    std::vector<uint32_t> face_stamp_;
    uint32_t pass_ = 0;
    bool candidates_closed_ = false;  // occluders started: no more candidates
    // The current placement's transforms.
    glm::mat4 to_clip_{1.0f}, model_view_{1.0f};
    glm::mat3 plane_normal_to_view_{1.0f};
    // One polygon's scratch space, sized for the largest face once.
    std::vector<glm::vec4> clip_;
    std::vector<uint32_t> clip_keys_;
    std::vector<ScreenVertex> screen_;
    std::vector<uint8_t> screen_shared_;  // per screen edge (from vertex i to i + 1)
    std::vector<EdgeLine> lines_;
    uint32_t projected_count_ = 0;
};

}  // namespace nq
