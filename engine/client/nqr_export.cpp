#include "client/nqr_export.h"

#include <algorithm>

#include "client/client_math.h"

namespace nq {
namespace {

void copy3(const Vec3& from, float (&to)[3]) {
    std::copy(from.begin(), from.end(), to);
}

}  // namespace

void export_entity(const VisibleEntity& v, nqr_model_id model, nqr_entity& out) {
    out.size = sizeof(nqr_entity);
    out.number = v.number;
    out.model = model;
    out.flags = v.flags;
    copy3(v.origin, out.origin);
    copy3(v.angles, out.angles);
    out.scale = v.scale;
    out.frame = static_cast<uint32_t>(std::max(v.frame, 0));
    out.pose0 = v.pose.pose0;
    out.pose1 = v.pose.pose1;
    out.lerp = v.pose.lerp;
    out.skin_image = v.skin_image;
    out.skin = static_cast<uint32_t>(std::max(v.skin, 0));
    out.top_color = v.top_color;
    out.bottom_color = v.bottom_color;
    out.has_translation = v.has_translation ? 1 : 0;
    out.alpha = v.alpha;
    out.effects = static_cast<uint32_t>(v.effects);
}

void export_camera_pose(const ViewResult& view, nqr_camera& out) {
    out.size = sizeof(nqr_camera);
    copy3(view.origin, out.origin);
    copy3(view.angles, out.angles);
    const Basis basis = angle_vectors(view.angles);
    copy3(basis.forward, out.forward);
    copy3(basis.right, out.right);
    copy3(basis.up, out.up);
}

size_t export_particles(std::span<const Particle> particles, std::span<nqr_particle> out) {
    const size_t n = std::min(particles.size(), out.size());
    for (size_t i = 0; i < n; ++i) {
        nqr_particle& p = out[i];
        p.size = sizeof(nqr_particle);
        copy3(particles[i].origin, p.origin);
        p.color = particles[i].color;
        p.pad[0] = p.pad[1] = p.pad[2] = 0;
        p.alpha = 1.0f;  // Quake's particles are opaque
    }
    return n;
}

size_t export_dynamic_lights(const DynamicLights& lights, double time, std::span<nqr_dlight> out) {
    size_t n = 0;
    for (const DynamicLight& l : lights.all()) {
        if (n == out.size()) break;
        if (!l.lit(time)) continue;
        nqr_dlight& d = out[n++];
        d.size = sizeof(nqr_dlight);
        copy3(l.origin, d.origin);
        d.radius = l.radius;
        copy3(l.color, d.color);
    }
    return n;
}

}  // namespace nq
