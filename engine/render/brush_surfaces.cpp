#include "render/brush_surfaces.h"

#include <cmath>

#include "render/brush_textures.h"

namespace nq {

namespace {

uint32_t surfedge_vertex(const Bsp& bsp, int32_t surfedge) {
    // The parser checked every surfedge against the edge count and rejected INT_MIN.
    return surfedge >= 0 ? bsp.edges[static_cast<uint32_t>(surfedge)].v[0]
                         : bsp.edges[static_cast<uint32_t>(-surfedge)].v[1];
}

int32_t surface_texture(const Bsp& bsp, const BspTexinfo& texinfo) {
    return texinfo.miptex < bsp.textures.size() ? static_cast<int32_t>(texinfo.miptex) : -1;
}

uint32_t surface_flags(const Bsp& bsp, const BspFace& face, int32_t texture) {
    uint32_t flags = face.back_side ? uint32_t{NQR_SURFACE_PLANE_BACK} : 0u;
    if (texture < 0) return flags;
    const uint32_t texture_flags = texture_flags_for_name(bsp.textures[texture].name);
    if (texture_flags & NQR_TEXTURE_SKY) flags |= NQR_SURFACE_SKY;
    if (texture_flags & NQR_TEXTURE_LIQUID) flags |= NQR_SURFACE_LIQUID;
    return flags;
}

void set_plane(const Bsp& bsp, const BspFace& face, nqr_surface& s) {
    const BspPlane& plane = bsp.planes[face.plane];
    const float sign = face.back_side ? -1.0f : 1.0f;
    for (int i = 0; i < 3; ++i) s.normal[i] = sign * plane.normal[i];
    s.dist = sign * plane.dist;
}

void set_lighting(const Bsp& bsp, const BspFace& face, nqr_surface& s) {
    for (int i = 0; i < kBspMaxLightStyles; ++i) s.styles[i] = face.styles[i];
    s.light_offset = face.has_lightmap() && !bsp.lighting.empty() ? face.light_offset : -1;
    for (int axis = 0; axis < 2; ++axis) {
        s.texture_mins[axis] = face.texture_mins[axis];
        s.extents[axis] = face.extents[axis];
    }
}

void append_polygon(const Bsp& bsp, const BspFace& face, BrushGeometry& out) {
    const uint32_t n = face.num_surfedges;
    for (uint32_t k = 0; k < n; ++k) {
        const uint32_t stored = k == 0 ? 0 : n - k;  // reverse, keeping vertex 0 first
        const uint32_t id = surfedge_vertex(bsp, bsp.surfedges[face.first_surfedge + stored]);
        out.vertex_ids.push_back(id);
        for (int i = 0; i < 3; ++i) out.positions.push_back(bsp.vertices[id][i]);
    }
}

bool usable_normal(const float n[3]) {
    const float length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    return std::isfinite(length) && std::fabs(length - 1.0f) < 0.01f;
}

// Newell's normal of the (counter-clockwise) polygon just appended for `s`, and its plane.
void normal_from_polygon(const BrushGeometry& geometry, nqr_surface& s) {
    double n[3] = {0, 0, 0};
    const float* p = geometry.positions.data() + size_t{s.first_vertex} * 3;
    for (uint32_t k = 0; k < s.num_vertices; ++k) {
        const float* a = p + 3 * k;
        const float* b = p + 3 * ((k + 1) % s.num_vertices);
        n[0] += (double{a[1]} - b[1]) * (double{a[2]} + b[2]);
        n[1] += (double{a[2]} - b[2]) * (double{a[0]} + b[0]);
        n[2] += (double{a[0]} - b[0]) * (double{a[1]} + b[1]);
    }
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(length > 0)) return;  // a polygon without area: nothing better to offer
    for (int i = 0; i < 3; ++i) s.normal[i] = float(n[i] / length);
    s.dist = s.normal[0] * p[0] + s.normal[1] * p[1] + s.normal[2] * p[2];
}

nqr_surface surface_record(const Bsp& bsp, const BspFace& face, uint32_t first_vertex) {
    nqr_surface s{};
    s.size = sizeof(nqr_surface);
    s.first_vertex = first_vertex;
    s.num_vertices = face.num_surfedges;
    set_plane(bsp, face, s);
    const BspTexinfo& texinfo = bsp.texinfo[face.texinfo];
    for (int i = 0; i < 4; ++i) {
        s.tex_s[i] = texinfo.vecs[0][i];
        s.tex_t[i] = texinfo.vecs[1][i];
    }
    s.texture = surface_texture(bsp, texinfo);
    s.flags = surface_flags(bsp, face, s.texture);
    set_lighting(bsp, face, s);
    return s;
}

}  // namespace

BrushGeometry build_brush_geometry(const Bsp& bsp) {
    BrushGeometry out;
    out.surfaces.reserve(bsp.faces.size());
    out.vertex_ids.reserve(bsp.surfedges.size());
    out.positions.reserve(bsp.surfedges.size() * 3);
    size_t repaired = 0;
    for (const BspFace& face : bsp.faces) {
        const auto first_vertex = static_cast<uint32_t>(out.vertex_ids.size());
        out.surfaces.push_back(surface_record(bsp, face, first_vertex));
        append_polygon(bsp, face, out);
        if (!usable_normal(out.surfaces.back().normal)) {
            normal_from_polygon(out, out.surfaces.back());
            ++repaired;
        }
    }
    if (repaired > 0) {
        out.warnings.push_back(std::to_string(repaired) + " faces lie on planes without a " +
                               "unit normal; their normals come from their polygons");
    }
    return out;
}

}  // namespace nq
