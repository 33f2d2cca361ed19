// The faces of a BSP as nqr_surface records with their polygons (one surface per face, in face
// order, so surface index = BSP face index).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "formats/bsp.h"
#include "nqr_renderer.h"

namespace nq {

struct BrushGeometry {
    std::vector<nqr_surface> surfaces;  // parallel to Bsp::faces
    std::vector<float> positions;       // x, y, z per polygon vertex
    std::vector<uint32_t> vertex_ids;   // BSP vertex index per polygon vertex
    std::vector<std::string> warnings;
};

// Polygon vertices come from the face's surfedges (a negative surfedge walks its edge from
// v[1] to v[0]). Quake stores them clockwise seen from the front; the ABI wants them
// counter-clockwise, so the order is reversed, keeping the first vertex first: v0, vn-1, .., v1.
// Normal and dist are the plane's, negated for faces on the plane's back side. A plane without a
// usable normal (b_exbox2.bsp has one of length 0) gets the polygon's own normal instead, with a
// warning, so renderers never see a zero normal.
// texture_mins/extents are the parser's (bsp_lightmap.cpp): floor/ceil of the face's texel
// bounds / 16, computed in double precision as light tools do (engines that sum in float can be
// one 16-texel step off on faces with large coordinates, and then disagree with the light data).
BrushGeometry build_brush_geometry(const Bsp& bsp);

}  // namespace nq
