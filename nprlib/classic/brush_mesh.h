// CPU side of a brush model (the world and its submodels share one): one vertex per polygon
// corner with its texel coordinates and lightmap atlas coordinates, triangle-fan indices per
// surface, and each surface's place in the lightmap atlas.
#pragma once

#include <cstdint>
#include <vector>

#include "classic/lightmap_builder.h"
#include "nqr_renderer.h"

namespace nq::npr::classic {

struct BrushVertex {
    float position[3];
    float texel[2];     // texture-space s, t in texels (divide by the texture size to sample)
    float lightmap[3];  // atlas u, v (0..1) and page
    float normal[3];
};

struct BrushSurfaceMesh {
    uint32_t first_index = 0, index_count = 0;  // index_count 0: nothing to draw (bad data)
    int lightmap_page = -1;                     // -1: no lightmap (sky, liquid, none fits)
    int lightmap_x = 0, lightmap_y = 0;
    SurfaceLightmapSize lightmap_size;
};

struct BrushMesh {
    std::vector<BrushVertex> vertices;
    std::vector<uint32_t> indices;
    std::vector<BrushSurfaceMesh> surfaces;  // parallel to nqr_brush_model::surfaces
    int lightmap_page_size = 0;
    int lightmap_pages = 0;
    int largest_lightmap_samples = 0;
};

// Whether a surface is drawn with a lightmap (not sky, not liquid: Quake lights neither).
bool surface_is_lightmapped(const nqr_brush_model& brush, const nqr_surface& surface);

BrushMesh build_brush_mesh(const nqr_brush_model& brush, int lightmap_page_size);

}  // namespace nq::npr::classic
