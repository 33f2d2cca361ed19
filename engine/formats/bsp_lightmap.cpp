// Lightmap layout of every face, derived the way engines and light tools do: project the face's
// vertices on the texinfo axes, snap the texel bounds outwards to multiples of 16, and allot one
// lightmap sample per 16 texels plus one (extents / 16 + 1) per axis and per light style.
#include <algorithm>
#include <cmath>
#include <limits>

#include "formats/bsp_internal.h"

namespace nq::bsp_detail {

namespace {

// Snapped bounds beyond this (in 16-texel steps) cannot be expressed in int32 texels.
constexpr double kMaxLightmapStep = double{1 << 25};
constexpr int32_t kClassicMaxExtent = 256;  // what original engines accept

uint32_t count_styles(const BspFace& face) {
    uint32_t n = 0;
    while (n < face.styles.size() && face.styles[n] != kBspNoLightStyle) ++n;
    return n;
}

uint32_t face_vertex(const Bsp& bsp, const BspFace& face, uint32_t k) {
    const int32_t e = bsp.surfedges[face.first_surfedge + k];
    // Indices were checked at read time; INT_MIN was rejected, so -e cannot overflow.
    return e >= 0 ? bsp.edges[static_cast<uint32_t>(e)].v[0]
                  : bsp.edges[static_cast<uint32_t>(-e)].v[1];
}

// Sets texture_mins and extents; false when the coordinates are too large to snap.
bool snap_texel_bounds(const Bsp& bsp, BspFace& face) {
    const BspTexinfo& tex = bsp.texinfo[face.texinfo];
    for (int axis = 0; axis < 2; ++axis) {
        double lo = std::numeric_limits<double>::max();
        double hi = std::numeric_limits<double>::lowest();
        const auto& v = tex.vecs[axis];
        for (uint32_t k = 0; k < face.num_surfedges; ++k) {
            const BspVec3& p = bsp.vertices[face_vertex(bsp, face, k)];
            // Double precision, as light tools compute it, so sample counts agree with them.
            const double s =
                double{p[0]} * v[0] + double{p[1]} * v[1] + double{p[2]} * v[2] + double{v[3]};
            lo = std::min(lo, s);
            hi = std::max(hi, s);
        }
        const double step_lo = std::floor(lo / 16);
        const double step_hi = std::ceil(hi / 16);
        if (!(std::fabs(step_lo) <= kMaxLightmapStep && std::fabs(step_hi) <= kMaxLightmapStep)) {
            return false;
        }
        face.texture_mins[axis] = static_cast<int32_t>(step_lo) * 16;
        face.extents[axis] = static_cast<int32_t>(step_hi - step_lo) * 16;
    }
    return true;
}

}  // namespace

void compute_face_lightmaps(const ReadContext& ctx) {
    Bsp& bsp = ctx.out;
    const uint64_t lighting_bytes = ctx.lumps[kLighting].length;
    size_t oversized = 0;
    for (size_t i = 0; i < bsp.faces.size(); ++i) {
        BspFace& face = bsp.faces[i];
        face.num_styles = count_styles(face);
        const bool snapped = snap_texel_bounds(bsp, face);
        if (!face.has_lightmap()) {
            if (!snapped) face.texture_mins = face.extents = {0, 0};
            continue;
        }
        const std::string what = "face " + std::to_string(i);
        if (!snapped) {
            ctx.fail_record(kFaces, i,
                            what + " texture coordinates are too large to place " + "its lightmap");
        }
        face.lightmap_width = static_cast<uint32_t>(face.extents[0] / 16 + 1);
        face.lightmap_height = static_cast<uint32_t>(face.extents[1] / 16 + 1);
        const uint64_t bytes =
            uint64_t{face.lightmap_width} * face.lightmap_height * face.num_styles;
        const auto offset = static_cast<uint64_t>(face.light_offset);
        if (offset > lighting_bytes || bytes > lighting_bytes - offset) {
            ctx.fail_record(
                kFaces, i,
                what + " lightmap [" + std::to_string(offset) + ", +" + std::to_string(bytes) +
                    ") (" + std::to_string(face.lightmap_width) + "x" +
                    std::to_string(face.lightmap_height) + " x " + std::to_string(face.num_styles) +
                    " styles) lies outside the lighting lump (" + std::to_string(lighting_bytes) +
                    " bytes)");
        }
        if (face.extents[0] > kClassicMaxExtent || face.extents[1] > kClassicMaxExtent) {
            ++oversized;
        }
    }
    if (oversized > 0) {
        bsp.warnings.push_back(std::to_string(oversized) + " lit faces have lightmap extents " +
                               "above 256 texels (original engines refuse such maps)");
    }
}

}  // namespace nq::bsp_detail
