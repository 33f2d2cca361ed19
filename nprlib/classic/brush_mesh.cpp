#include "classic/brush_mesh.h"

#include <algorithm>

#include "abi/abi_access.h"
#include "classic/lightmap_packer.h"

namespace nq::npr::classic {
namespace {

float dot_plane(const float* position, const float* plane) {
    return position[0] * plane[0] + position[1] * plane[1] + position[2] * plane[2] + plane[3];
}

bool surface_polygon_valid(const nqr_brush_model& brush, const nqr_surface& surface) {
    return brush.positions != nullptr && surface.num_vertices >= 3 &&
           surface.first_vertex <= brush.num_vertices &&
           surface.num_vertices <= brush.num_vertices - surface.first_vertex;
}

void place_lightmap(const nqr_brush_model& brush, const nqr_surface& surface,
                    LightmapPacker& packer, BrushSurfaceMesh& mesh) {
    if (!surface_is_lightmapped(brush, surface)) return;
    mesh.lightmap_size = surface_lightmap_size(surface);
    if (mesh.lightmap_size.samples() == 0) return;
    const LightmapPlacement placement =
        packer.place(mesh.lightmap_size.width, mesh.lightmap_size.height);
    mesh.lightmap_page = placement.page;
    mesh.lightmap_x = placement.x;
    mesh.lightmap_y = placement.y;
}

BrushVertex make_vertex(const nqr_surface& surface, const BrushSurfaceMesh& mesh,
                        const float* position, int page_size) {
    BrushVertex vertex{};
    std::copy(position, position + 3, vertex.position);
    const float s = dot_plane(position, surface.tex_s);
    const float t = dot_plane(position, surface.tex_t);
    vertex.texel[0] = s;
    vertex.texel[1] = t;
    if (mesh.lightmap_page >= 0) {
        // Sample centres sit at (sample * 16 + 8) texels from the surface's texture minimum.
        const float atlas_texels = static_cast<float>(page_size) * 16.0f;
        vertex.lightmap[0] =
            (s - surface.texture_mins[0] + mesh.lightmap_x * 16 + 8) / atlas_texels;
        vertex.lightmap[1] =
            (t - surface.texture_mins[1] + mesh.lightmap_y * 16 + 8) / atlas_texels;
        vertex.lightmap[2] = static_cast<float>(mesh.lightmap_page);
    }
    std::copy(surface.normal, surface.normal + 3, vertex.normal);
    return vertex;
}

}  // namespace

bool surface_is_lightmapped(const nqr_brush_model& brush, const nqr_surface& surface) {
    if (surface.flags & (NQR_SURFACE_SKY | NQR_SURFACE_LIQUID)) return false;
    if (surface.texture >= 0 && static_cast<uint32_t>(surface.texture) < brush.num_textures) {
        const nqr_texture& texture =
            abi_element(brush.textures, static_cast<uint32_t>(surface.texture));
        if (texture.flags & (NQR_TEXTURE_SKY | NQR_TEXTURE_LIQUID)) return false;
    }
    return true;
}

BrushMesh build_brush_mesh(const nqr_brush_model& brush, int lightmap_page_size) {
    BrushMesh mesh;
    mesh.lightmap_page_size = lightmap_page_size;
    mesh.surfaces.resize(brush.num_surfaces);
    LightmapPacker packer(lightmap_page_size);
    for (uint32_t i = 0; i < brush.num_surfaces; ++i) {
        const nqr_surface& surface = abi_element(brush.surfaces, i);
        BrushSurfaceMesh& surface_mesh = mesh.surfaces[i];
        if (!surface_polygon_valid(brush, surface)) continue;
        place_lightmap(brush, surface, packer, surface_mesh);
        if (surface_mesh.lightmap_page >= 0) {
            mesh.largest_lightmap_samples =
                std::max(mesh.largest_lightmap_samples, surface_mesh.lightmap_size.samples());
        }
        const auto first_vertex = static_cast<uint32_t>(mesh.vertices.size());
        for (uint32_t v = 0; v < surface.num_vertices; ++v) {
            const float* position = brush.positions + (surface.first_vertex + v) * 3u;
            mesh.vertices.push_back(
                make_vertex(surface, surface_mesh, position, lightmap_page_size));
        }
        surface_mesh.first_index = static_cast<uint32_t>(mesh.indices.size());
        for (uint32_t v = 1; v + 1 < surface.num_vertices; ++v) {  // triangle fan
            mesh.indices.insert(mesh.indices.end(),
                                {first_vertex, first_vertex + v, first_vertex + v + 1});
        }
        surface_mesh.index_count =
            static_cast<uint32_t>(mesh.indices.size()) - surface_mesh.first_index;
    }
    mesh.lightmap_pages = packer.page_count();
    return mesh;
}

}  // namespace nq::npr::classic
