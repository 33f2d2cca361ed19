// Where a world point lands on a W x H screenshot, computed here from Quake's conventions alone
// (none of the engine's matrix code), so a test can check where the engine drew something:
//   - angles are (pitch, yaw, roll) in degrees; positive pitch looks down;
//   - forward = (cos p cos y, cos p sin y, -sin p); right and up as Quake's AngleVectors;
//   - the horizontal field of view spans the width; pixels are square, so one focal length
//     (W/2 / tan(fov_x/2)) serves both axes; image rows run top-down.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <span>

#include "formats/mdl.h"

namespace nq::test {

using V3 = std::array<float, 3>;

inline float dot3(const V3& a, const V3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

struct QuakeAxes {
    V3 forward, right, up;
};

inline QuakeAxes quake_axes(const V3& angles_degrees) {
    const double k = M_PI / 180.0;
    double sp = std::sin(angles_degrees[0] * k), cp = std::cos(angles_degrees[0] * k);
    double sy = std::sin(angles_degrees[1] * k), cy = std::cos(angles_degrees[1] * k);
    double sr = std::sin(angles_degrees[2] * k), cr = std::cos(angles_degrees[2] * k);
    QuakeAxes a;
    a.forward = {float(cp * cy), float(cp * sy), float(-sp)};
    a.right = {float(-sr * sp * cy + cr * sy), float(-sr * sp * sy - cr * cy), float(-sr * cp)};
    a.up = {float(cr * sp * cy + sr * sy), float(cr * sp * sy - sr * cy), float(cr * cp)};
    return a;
}

struct ScreenPoint {
    float x = 0, y = 0;  // pixels from the top-left corner
};

class QuakeProjector {
  public:
    static constexpr float kNear = 4.0f;  // GLQuake's near plane

    QuakeProjector(const V3& eye, const V3& angles, float fov_x_degrees, int width, int height)
        : eye_(eye),
          axes_(quake_axes(angles)),
          width_(width),
          height_(height),
          focal_(0.5f * width / std::tan(fov_x_degrees * float(M_PI) / 360.0f)) {}

    // Nothing when the point lies behind the near plane.
    std::optional<ScreenPoint> project(const V3& p) const {
        V3 d{p[0] - eye_[0], p[1] - eye_[1], p[2] - eye_[2]};
        float z = dot3(d, axes_.forward);
        if (z <= kNear) return std::nullopt;
        return ScreenPoint{0.5f * width_ + dot3(d, axes_.right) / z * focal_,
                           0.5f * height_ - dot3(d, axes_.up) / z * focal_};
    }
    // Whether every point lies beyond one and the same side of the view frustum (left, right,
    // top, bottom or near): then nothing between them can be on screen.
    bool all_outside(std::span<const V3> points) const {
        const float tx = 0.5f * width_ / focal_, ty = 0.5f * height_ / focal_;
        std::array<bool, 5> all{true, true, true, true, true};
        for (const V3& p : points) {
            V3 d{p[0] - eye_[0], p[1] - eye_[1], p[2] - eye_[2]};
            float x = dot3(d, axes_.right), y = dot3(d, axes_.up), z = dot3(d, axes_.forward);
            all[0] = all[0] && x > z * tx;
            all[1] = all[1] && x < -z * tx;
            all[2] = all[2] && y > z * ty;
            all[3] = all[3] && y < -z * ty;
            all[4] = all[4] && z <= kNear;
        }
        return !points.empty() && (all[0] || all[1] || all[2] || all[3] || all[4]);
    }
    float distance(const V3& p) const {
        V3 d{p[0] - eye_[0], p[1] - eye_[1], p[2] - eye_[2]};
        return std::sqrt(dot3(d, d));
    }

  private:
    V3 eye_;
    QuakeAxes axes_;
    int width_, height_;
    float focal_;
};

// A screen rectangle, in pixels (min inclusive, max exclusive after rounding outwards).
struct ScreenBox {
    float x0 = 1e9f, y0 = 1e9f, x1 = -1e9f, y1 = -1e9f;
    bool empty() const { return x1 < x0; }
    void add(const ScreenPoint& p) {
        x0 = std::min(x0, p.x), y0 = std::min(y0, p.y);
        x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
    }
    ScreenBox grown(float by) const { return {x0 - by, y0 - by, x1 + by, y1 + by}; }
    bool contains(float x, float y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
    bool overlaps(const ScreenBox& o) const {
        return !empty() && !o.empty() && x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1;
    }
    bool inside(int width, int height, float margin) const {
        return x0 >= margin && y0 >= margin && x1 <= width - margin && y1 <= height - margin;
    }
    float width() const { return x1 - x0; }
    float height() const { return y1 - y0; }
};

// The MDL's poses in the order the renderer numbers them (frames in order, group poses in
// order).
inline std::vector<const MdlPose*> numbered_poses(const Mdl& mdl) {
    std::vector<const MdlPose*> poses;
    for (const MdlFrame& f : mdl.frames) {
        for (const MdlPose& p : f.poses) poses.push_back(&p);
    }
    return poses;
}

// World positions of a pose's vertices for an alias entity at `origin` with `angles` and
// `scale`: model = scale_mdl * v + origin_mdl, then the model's +X, +Y, +Z axes become the
// entity's forward, left and up. Alias models pitch the other way from the view (a positive
// pitch raises the nose), so the axes are those of the view angles (-pitch, yaw, roll).
inline std::vector<V3> posed_vertices_world(const Mdl& mdl, const MdlPose& pose, const V3& origin,
                                            const V3& angles, float scale) {
    QuakeAxes axes = quake_axes({-angles[0], angles[1], angles[2]});
    std::vector<V3> out;
    out.reserve(pose.vertices.size());
    for (const TriVertex& v : pose.vertices) {
        V3 m;
        for (int i = 0; i < 3; ++i) {
            m[i] = scale * (mdl.header.scale[i] * v.v[i] + mdl.header.scale_origin[i]);
        }
        V3 w;
        for (int i = 0; i < 3; ++i) {
            w[i] = origin[i] + m[0] * axes.forward[i] - m[1] * axes.right[i] + m[2] * axes.up[i];
        }
        out.push_back(w);
    }
    return out;
}

}  // namespace nq::test
