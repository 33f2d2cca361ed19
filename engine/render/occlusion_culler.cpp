#include "render/occlusion_culler.h"

#include <algorithm>
#include <climits>
#include <cmath>

#include "render/view_transform.h"

namespace nq {

namespace {

constexpr size_t kMaxCandidates = 4096;
constexpr size_t kKeptPoints = 65536;
constexpr int kMaxViewSize = 16384;
// How far pixel centres must lie inside an outline edge: four times the farthest a GPU's
// sub-pixel snapping (8 bits: vertices rounded to 1/256 pixel) moves an edge, and far more than
// the rounding of either side's transform (about 1/10000 pixel at 1000 pixels from the axis).
constexpr float kOutlineMargin = 1.0f / 128.0f;
// Depth is lowered by its change across this distance: the GPU's snapped vertices move the
// plane it interpolates by less.
constexpr float kDepthSnapSlack = 1.0f / 64.0f;
// A hidden box must be farther than the world by this share of the distance plus one unit:
// 24-bit depth and the float arithmetic of both sides stay far inside it.
constexpr float kRelativeDepthMargin = 1.0e-3f;
constexpr float kAbsoluteDepthMargin = 1.0f;
// Faces seen this close to edge-on are not counted as drawn (their winding on screen may
// flip).
constexpr float kMinEyeDistance = 0.1f;

// The line through p and q as a x + b y + c, positive on its left (inside of a counter-
// clockwise polygon walking from p to q).
glm::vec3 line_through(const glm::vec2& p, const glm::vec2& q) {
    return {p.y - q.y, q.x - p.x, p.x * q.y - q.x * p.y};
}

int pixel_at_or_after(float centre_coordinate) {  // first pixel whose centre is >= it
    return static_cast<int>(std::ceil(centre_coordinate - 0.5f));
}
int pixel_at_or_before(float centre_coordinate) {
    return static_cast<int>(std::floor(centre_coordinate - 0.5f));
}

}  // namespace

OcclusionCuller::OcclusionCuller(const OccluderMesh& mesh) : mesh_(mesh) {
    candidates_.resize(kMaxCandidates);
    points_.resize(kKeptPoints);
    face_stamp_.assign(mesh.faces().size(), 0);
    const size_t most = size_t{mesh.max_polygon_vertices()} + 2;  // a near-plane cut adds one
    clip_.resize(most);
    clip_keys_.resize(most);
    screen_.resize(most);
    screen_shared_.resize(most);
    lines_.resize(most);
}

void OcclusionCuller::resize(int width, int height) {
    if (width == width_ && height == height_) return;
    width_ = width;
    height_ = height;
    inverse_w_.assign(size_t(width) * size_t(height), 0.0f);
    row_lo_.assign(height, INT_MAX);
    row_hi_.assign(height, -1);
    rows_lo_ = 0;
    rows_hi_ = -1;
}

void OcclusionCuller::begin_frame(const nqr_camera& camera) {
    for (int r = rows_lo_; r <= rows_hi_; ++r) {
        row_lo_[r] = INT_MAX;
        row_hi_[r] = -1;
    }
    candidate_count_ = 0;
    point_count_ = 0;
    candidates_closed_ = false;
    projection_ = load_matrix(camera.projection);
    view_ = load_matrix(camera.view);
    view_projection_ = load_matrix(camera.view_projection);
    eye_ = glm::vec3(camera.origin[0], camera.origin[1], camera.origin[2]);
    perspective_ = projection_[2][3] == -1.0f && projection_[3][3] == 0.0f &&
                   projection_[0][0] > 0.0f && projection_[1][1] > 0.0f &&
                   projection_[0][1] == 0.0f && projection_[1][0] == 0.0f;
    const int width = camera.viewport[2], height = camera.viewport[3];
    if (width < 1 || height < 1 || width > kMaxViewSize || height > kMaxViewSize) {
        perspective_ = false;
        return;
    }
    resize(width, height);
    rows_lo_ = height_;
    rows_hi_ = -1;
}

int32_t OcclusionCuller::add_box(const glm::mat4& placement, const glm::vec3& mins,
                                 const glm::vec3& maxs) {
    const glm::mat4 to_clip = view_projection_ * placement;
    ScreenExtent extent;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 local((corner & 1) ? maxs.x : mins.x, (corner & 2) ? maxs.y : mins.y,
                              (corner & 4) ? maxs.z : mins.z);
        extent.add(to_clip * glm::vec4(local, 1.0f));
    }
    return add_candidate(extent);
}

int32_t OcclusionCuller::add_points(const glm::mat4& placement, std::span<const glm::vec3> points) {
    const glm::mat4 to_clip = view_projection_ * placement;
    // Kept for triangle tests while they fit (a frame's candidates rarely need a tenth).
    const bool keep = points.size() <= points_.size() - point_count_;
    ScreenExtent extent;
    for (size_t i = 0; i < points.size(); ++i) {
        const glm::vec4 clip = to_clip * glm::vec4(points[i], 1.0f);
        if (keep) points_[point_count_ + i] = clip;
        extent.add(clip);
    }
    const int32_t id = add_candidate(extent);
    if (id >= 0 && keep) {
        candidates_[id].first_point = point_count_;
        candidates_[id].num_points = static_cast<uint32_t>(points.size());
        point_count_ += static_cast<uint32_t>(points.size());
    }
    return id;
}

void OcclusionCuller::ScreenExtent::add(const glm::vec4& clip) {
    crosses_near = crosses_near || !(clip.z + clip.w > 0.0f);
    nearest_w = std::min(nearest_w, clip.w);
    const glm::vec2 ndc(clip.x / clip.w, clip.y / clip.w);
    lo = glm::min(lo, ndc);
    hi = glm::max(hi, ndc);
}

bool OcclusionCuller::bound(const ScreenExtent& extent, Candidate& c, int32_t& reason) const {
    reason = kNotHideable;
    if (!perspective_ || extent.crosses_near) return false;
    const glm::vec2 size{float(width_), float(height_)};
    const glm::vec2 lo =
        glm::clamp((extent.lo + 1.0f) * 0.5f * size, glm::vec2(-2.0f), size + 2.0f);
    const glm::vec2 hi =
        glm::clamp((extent.hi + 1.0f) * 0.5f * size, glm::vec2(-2.0f), size + 2.0f);
    if (!std::isfinite(lo.x + lo.y + hi.x + hi.y)) return false;
    // One pixel more on every side for the GPU's own rounding.
    c.x0 = std::max(0, pixel_at_or_after(lo.x) - 1);
    c.y0 = std::max(0, pixel_at_or_after(lo.y) - 1);
    c.x1 = std::min(width_ - 1, pixel_at_or_before(hi.x) + 1);
    c.y1 = std::min(height_ - 1, pixel_at_or_before(hi.y) + 1);
    if (c.x0 > c.x1 || c.y0 > c.y1) {
        reason = kOffScreen;
        return false;
    }
    const float limit_w = (extent.nearest_w - kAbsoluteDepthMargin) / (1.0f + kRelativeDepthMargin);
    if (!(limit_w > 0.0f)) return false;
    c.nearest_inverse_w = 1.0f / limit_w;
    return true;
}

int32_t OcclusionCuller::add_candidate(const ScreenExtent& extent) {
    if (candidates_closed_ || candidate_count_ == candidates_.size()) return kNotHideable;
    Candidate c;
    int32_t reason = kNotHideable;
    if (!bound(extent, c, reason)) return reason;
    for (int r = c.y0; r <= c.y1; ++r) {
        row_lo_[r] = std::min(row_lo_[r], c.x0);
        row_hi_[r] = std::max(row_hi_[r], c.x1);
    }
    rows_lo_ = std::min(rows_lo_, c.y0);
    rows_hi_ = std::max(rows_hi_, c.y1);
    candidates_[candidate_count_] = c;
    return static_cast<int32_t>(candidate_count_++);
}

// Clears the pixels under the candidates once, before the first occluder.
void OcclusionCuller::begin_occluders() {
    if (candidates_closed_) return;
    candidates_closed_ = true;
    for (int r = rows_lo_; r <= rows_hi_; ++r) {
        if (row_lo_[r] > row_hi_[r]) continue;
        float* row = inverse_w_.data() + size_t(r) * size_t(width_);
        std::fill(row + row_lo_[r], row + row_hi_[r] + 1, 0.0f);
    }
}

void OcclusionCuller::set_placement(const glm::mat4& placement) {
    if (++pass_ == 0) {  // stamps wrapped: start over
        std::fill(face_stamp_.begin(), face_stamp_.end(), 0);
        pass_ = 1;
    }
    to_clip_ = view_projection_ * placement;
    model_view_ = view_ * placement;
    plane_normal_to_view_ = glm::transpose(glm::inverse(glm::mat3(model_view_)));
}

void OcclusionCuller::rasterize_world(std::span<const uint32_t> visible_surfaces) {
    if (candidate_count_ == 0) return;
    begin_occluders();
    set_placement(glm::mat4(1.0f));
    uint32_t drawn = 0;
    for (uint32_t s : visible_surfaces) drawn += stamp_if_drawn(s, eye_);
    if (drawn == 0) return;
    const std::span<const OccluderFace> faces = mesh_.faces();
    for (uint32_t s : visible_surfaces) {
        if (s < faces.size() && face_stamp_[s] == pass_) fill_face(faces[s]);
    }
}

void OcclusionCuller::rasterize_model(uint32_t first, uint32_t count, const glm::mat4& placement,
                                      const glm::vec3& eye_in_model) {
    const auto faces = static_cast<uint32_t>(mesh_.faces().size());
    if (candidate_count_ == 0 || first >= faces) return;
    begin_occluders();
    set_placement(placement);
    const uint32_t end = first + std::min(count, faces - first);
    uint32_t drawn = 0;
    for (uint32_t s = first; s < end; ++s) drawn += stamp_if_drawn(s, eye_in_model);
    if (drawn == 0) return;
    for (uint32_t s = first; s < end; ++s) {
        if (face_stamp_[s] == pass_) fill_face(mesh_.faces()[s]);
    }
}

// The plugin draws the faces whose front the eye sees.
bool OcclusionCuller::stamp_if_drawn(uint32_t surface, const glm::vec3& eye_in_model) {
    const std::span<const OccluderFace> faces = mesh_.faces();
    if (surface >= faces.size() || !faces[surface].occludes) return false;
    const OccluderFace& face = faces[surface];
    if (!(glm::dot(face.normal, eye_in_model) - face.dist > kMinEyeDistance)) return false;
    face_stamp_[surface] = pass_;
    return true;
}

bool OcclusionCuller::edge_shared(uint32_t vertex) const {
    for (uint32_t partner : mesh_.partners(vertex)) {
        if (face_stamp_[partner] == pass_) return true;
    }
    return false;
}

// Clip space, cut at the near plane (z = -w) as the GPU cuts it, then window coordinates. A
// point made on an edge is computed from the edge's ends in vertex id order, so both faces of
// a shared edge make the same point. False when nothing usable is left.
bool OcclusionCuller::project_face(const OccluderFace& face) {
    const uint32_t n = face.num_vertices;
    for (uint32_t k = 0; k < n; ++k) {
        clip_[k] = to_clip_ * glm::vec4(mesh_.position(face.first_vertex + k), 1.0f);
        clip_keys_[k] = mesh_.vertex_id(face.first_vertex + k);
        // Beyond the far plane the GPU cuts the face: leave it out rather than follow.
        if (!(clip_[k].w - clip_[k].z >= 0.0f)) return false;
    }
    uint32_t out = 0;
    const auto emit = [&](const glm::vec4& c, uint32_t key, bool shared_after) {
        screen_[out] = {
            {(c.x / c.w + 1.0f) * 0.5f * float(width_), (c.y / c.w + 1.0f) * 0.5f * float(height_)},
            key};
        screen_shared_[out++] = shared_after ? 1 : 0;
    };
    for (uint32_t k = 0; k < n; ++k) {
        const uint32_t j = k + 1 == n ? 0 : k + 1;
        const bool k_in = clip_[k].z + clip_[k].w >= 0.0f;
        const bool j_in = clip_[j].z + clip_[j].w >= 0.0f;
        const bool shared = edge_shared(face.first_vertex + k);
        if (k_in) emit(clip_[k], clip_keys_[k], shared);
        if (k_in == j_in) continue;
        const bool k_first = clip_keys_[k] <= clip_keys_[j];
        const glm::vec4& a = k_first ? clip_[k] : clip_[j];
        const glm::vec4& b = k_first ? clip_[j] : clip_[k];
        const float da = a.z + a.w, db = b.z + b.w;
        const glm::vec4 cut = a + (b - a) * (da / (da - db));
        // Leaving the view volume, the next edge runs along the near plane: an outline.
        emit(cut, kClipKey, k_in ? false : shared);
    }
    projected_count_ = out;
    if (out < 3) return false;
    for (uint32_t k = 0; k < out; ++k) {
        if (!std::isfinite(screen_[k].p.x) || !std::isfinite(screen_[k].p.y)) return false;
    }
    return true;
}

// Each edge as a half-plane. The line of a shared edge is computed from its ends in key order
// and negated for the face walking it the other way, so the two faces' tests are exact
// opposites: every pixel centre along it falls to one face or the other.
void OcclusionCuller::make_edge_lines(uint32_t count) {
    for (uint32_t k = 0; k < count; ++k) {
        const ScreenVertex& p = screen_[k];
        const ScreenVertex& q = screen_[k + 1 == count ? 0 : k + 1];
        const glm::vec3 l = p.key <= q.key ? line_through(p.p, q.p) : -line_through(q.p, p.p);
        const float t =
            screen_shared_[k] ? 0.0f : kOutlineMargin * (std::fabs(l.x) + std::fabs(l.y));
        lines_[k] = {l.x, l.y, l.z, t};
    }
}

// 1/w across the screen for the face's pushed-back plane, as a x + b y + c in window
// coordinates. The plane in view space is n_v . x = d_v (n_v: the normal through the inverse
// transpose of the placement's model-view; d_v from a point of the plane). A view-space point
// on the ray through NDC (u, v) at depth w is ((u + P20) w / P00, (v + P21) w / P11, -w);
// putting it in the plane gives 1/w as a linear function of u and v. False when the eye is not
// in front of the plane.
bool OcclusionCuller::face_depth_plane(const OccluderFace& face, glm::vec3& plane) const {
    const glm::vec3 n = glm::normalize(plane_normal_to_view_ * face.normal);
    const glm::vec3 on_plane =
        glm::vec3(model_view_ * glm::vec4(face.normal * face.back_dist, 1.0f));
    const float d = glm::dot(n, on_plane);
    if (!(d < -kMinEyeDistance)) return false;
    const float sx = projection_[0][0], sy = projection_[1][1];
    const float ox = projection_[2][0], oy = projection_[2][1];
    const float a = 2.0f * n.x / (sx * float(width_) * d);
    const float b = 2.0f * n.y / (sy * float(height_) * d);
    float c = (n.x * (ox - 1.0f) / sx + n.y * (oy - 1.0f) / sy - n.z) / d;
    c -= (std::fabs(a) + std::fabs(b)) * kDepthSnapSlack;
    plane = {a, b, c};
    return std::isfinite(a) && std::isfinite(b) && std::isfinite(c);
}

void OcclusionCuller::fill_face(const OccluderFace& face) {
    glm::vec3 depth;
    if (!face_depth_plane(face, depth) || !project_face(face)) return;
    const uint32_t count = projected_count_;
    make_edge_lines(count);
    float y_lo = INFINITY, y_hi = -INFINITY;
    for (uint32_t k = 0; k < count; ++k) {
        y_lo = std::min(y_lo, screen_[k].p.y);
        y_hi = std::max(y_hi, screen_[k].p.y);
    }
    y_lo = std::max(y_lo, -2.0f);
    y_hi = std::min(y_hi, float(height_) + 2.0f);
    const int first_row = std::max(rows_lo_, pixel_at_or_after(y_lo));
    const int last_row = std::min(rows_hi_, pixel_at_or_before(y_hi));
    for (int r = first_row; r <= last_row; ++r) {
        if (row_lo_[r] > row_hi_[r]) continue;
        const float y = float(r) + 0.5f;
        float x_lo = -2.0f, x_hi = float(width_) + 2.0f;
        for (uint32_t k = 0; k < count; ++k) {
            const EdgeLine& l = lines_[k];
            const float need = l.t - l.b * y - l.c;  // a x >= need
            if (l.a > 0.0f) {
                x_lo = std::max(x_lo, need / l.a);
            } else if (l.a < 0.0f) {
                x_hi = std::min(x_hi, need / l.a);
            } else if (need > 0.0f) {
                x_hi = -INFINITY;
            }
        }
        if (!(x_lo <= x_hi)) continue;
        const int i0 = std::max(row_lo_[r], pixel_at_or_after(x_lo));
        const int i1 = std::min(row_hi_[r], pixel_at_or_before(x_hi));
        float* row = inverse_w_.data() + size_t(r) * size_t(width_);
        const float base = depth.y * y + depth.z + 0.5f * depth.x;
        for (int i = i0; i <= i1; ++i) {
            const float value = base + depth.x * float(i);
            row[i] = row[i] < value ? value : row[i];
        }
    }
}

bool OcclusionCuller::hidden(int32_t candidate) const {
    if (!candidates_closed_ || candidate < 0 || uint32_t(candidate) >= candidate_count_) {
        return false;
    }
    return rectangle_hidden(candidates_[candidate]);
}

bool OcclusionCuller::triangle_hidden(int32_t candidate, uint32_t a, uint32_t b, uint32_t c) const {
    if (!candidates_closed_ || candidate < 0 || uint32_t(candidate) >= candidate_count_) {
        return false;
    }
    const Candidate& owner = candidates_[candidate];
    if (a >= owner.num_points || b >= owner.num_points || c >= owner.num_points) return false;
    ScreenExtent extent;
    for (uint32_t i : {a, b, c}) extent.add(points_[owner.first_point + i]);
    Candidate triangle;
    int32_t reason = kNotHideable;
    if (!bound(extent, triangle, reason)) return reason == kOffScreen;
    // Inside the owner's rectangle by construction; checked, as only that was rasterised.
    if (triangle.x0 < owner.x0 || triangle.x1 > owner.x1 || triangle.y0 < owner.y0 ||
        triangle.y1 > owner.y1) {
        return false;
    }
    return rectangle_hidden(triangle);
}

bool OcclusionCuller::rectangle_hidden(const Candidate& c) const {
    for (int r = c.y0; r <= c.y1; ++r) {
        const float* row = inverse_w_.data() + size_t(r) * size_t(width_);
        for (int x = c.x0; x <= c.x1; ++x) {
            if (!(row[x] > c.nearest_inverse_w)) return false;
        }
    }
    return true;
}

float OcclusionCuller::inverse_w_at(int x, int y) const {
    if (x < 0 || y < 0 || x >= width_ || y >= height_) return 0.0f;
    if (y < rows_lo_ || y > rows_hi_ || x < row_lo_[y] || x > row_hi_[y]) return 0.0f;
    return inverse_w_[size_t(y) * size_t(width_) + size_t(x)];
}

}  // namespace nq
