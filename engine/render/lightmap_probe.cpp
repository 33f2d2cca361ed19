#include "render/lightmap_probe.h"

#include <algorithm>
#include <cmath>

#include "render/brush_textures.h"

namespace nq {

namespace {

double plane_distance(const BspPlane& plane, const glm::dvec3& p) {
    return plane.normal[0] * p.x + plane.normal[1] * p.y + plane.normal[2] * p.z - plane.dist;
}

uint32_t face_texture_flags(const Bsp& bsp, const BspFace& face) {
    const uint32_t miptex = bsp.texinfo[face.texinfo].miptex;
    return miptex < bsp.textures.size() ? texture_flags_for_name(bsp.textures[miptex].name) : 0u;
}

struct Walker {
    const Bsp& bsp;
    bool stop_at_sky;
    SurfaceHit hit;

    // Whether the point lies on `face`'s lightmap rectangle; sets hit if so.
    bool test_face(uint32_t index, const glm::dvec3& p) {
        const BspFace& face = bsp.faces[index];
        const BspTexinfo& tex = bsp.texinfo[face.texinfo];
        double st[2];
        for (int axis = 0; axis < 2; ++axis) {
            const auto& v = tex.vecs[axis];
            st[axis] = v[0] * p.x + v[1] * p.y + v[2] * p.z + v[3] - face.texture_mins[axis];
            if (st[axis] < 0 || st[axis] > face.extents[axis]) return false;
        }
        hit = {index, glm::vec3(p), float(st[0]), float(st[1]), false};
        return true;
    }

    // 1: a lit face was hit, -1: a sky face stopped the ray, 0: keep looking.
    int test_node_faces(const BspNode& node, const glm::dvec3& p) {
        const auto end =
            std::min<size_t>(size_t{node.first_face} + node.num_faces, bsp.faces.size());
        for (size_t i = node.first_face; i < end; ++i) {
            const uint32_t flags = face_texture_flags(bsp, bsp.faces[i]);
            if (flags & NQR_TEXTURE_LIQUID) continue;
            if (flags & NQR_TEXTURE_SKY) {
                if (stop_at_sky && test_face(uint32_t(i), p)) {
                    hit.sky = true;
                    return -1;
                }
                continue;
            }
            if (test_face(uint32_t(i), p)) return 1;
        }
        return 0;
    }

    // True once the ray has ended on a face.
    bool walk(int32_t node, const glm::dvec3& a, const glm::dvec3& b, int depth) {
        if (node < 0 || depth > kBspMaxTreeDepth) return false;
        if (static_cast<size_t>(node) >= bsp.nodes.size()) return false;
        const BspNode& n = bsp.nodes[node];
        const BspPlane& plane = bsp.planes[n.plane];
        const double da = plane_distance(plane, a), db = plane_distance(plane, b);
        const int near = da < 0 ? 1 : 0;
        if ((db < 0) == (da < 0)) return walk(n.children[near], a, b, depth + 1);
        const glm::dvec3 mid = a + (b - a) * (da / (da - db));
        if (walk(n.children[near], a, mid, depth + 1)) return true;
        if (test_node_faces(n, mid) != 0) return true;
        return walk(n.children[near ^ 1], mid, b, depth + 1);
    }
};

// One style's sample at integer sample coordinates, per channel.
glm::vec3 rgb_sample(std::span<const uint8_t> rgb, size_t index) {
    if (index * 3 + 2 >= rgb.size()) return glm::vec3(0.0f);
    return {rgb[index * 3], rgb[index * 3 + 1], rgb[index * 3 + 2]};
}

}  // namespace

std::optional<SurfaceHit> first_surface_along(const Bsp& bsp, const glm::vec3& start,
                                              const glm::vec3& end, bool stop_at_sky) {
    if (bsp.models.empty()) return std::nullopt;
    Walker walker{bsp, stop_at_sky, {}};
    if (!walker.walk(bsp.models[0].headnodes[0], glm::dvec3(start), glm::dvec3(end), 0)) {
        return std::nullopt;
    }
    return walker.hit;
}

glm::vec3 sample_lightmap(const Bsp& bsp, std::span<const uint8_t> rgb, const SurfaceHit& hit,
                          std::span<const float> lightstyles) {
    const BspFace& face = bsp.faces[hit.face];
    if (!face.has_lightmap() || hit.sky) return glm::vec3(0.0f);
    const uint32_t w = face.lightmap_width, h = face.lightmap_height;
    // Sample (i, j) sits at texel (16 i, 16 j) from texture_mins.
    const float u = std::clamp(hit.s / 16.0f, 0.0f, float(w - 1));
    const float v = std::clamp(hit.t / 16.0f, 0.0f, float(h - 1));
    const uint32_t i0 = uint32_t(u), j0 = uint32_t(v);
    const uint32_t i1 = std::min(i0 + 1, w - 1), j1 = std::min(j0 + 1, h - 1);
    const float fu = u - float(i0), fv = v - float(j0);

    glm::vec3 total(0.0f);
    for (uint32_t k = 0; k < face.num_styles; ++k) {
        const uint8_t style = face.styles[k];
        const float scale = style < lightstyles.size() ? lightstyles[style] : 1.0f;
        const size_t base = size_t(face.light_offset) + size_t(k) * w * h;
        const glm::vec3 top =
            glm::mix(rgb_sample(rgb, base + j0 * w + i0), rgb_sample(rgb, base + j0 * w + i1), fu);
        const glm::vec3 bottom =
            glm::mix(rgb_sample(rgb, base + j1 * w + i0), rgb_sample(rgb, base + j1 * w + i1), fu);
        total += glm::mix(top, bottom, fv) * scale;
    }
    return total;
}

}  // namespace nq
