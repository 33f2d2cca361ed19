// Everything the GPU needs to draw one nqr_brush_model (the world with its inline submodels, or
// a b_*.bsp item box): vertex/index buffers, textures, the lightmap atlas with per-surface light
// state, and the batching arrays, all sized at creation so that frames never allocate.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "classic/brush_mesh.h"
#include "classic/brush_textures.h"
#include "classic/lightmap_atlas.h"
#include "classic/lightmap_builder.h"
#include "classic/surface_batches.h"
#include "gl/handles.h"
#include "nqr_renderer.h"

namespace nq::npr::classic {

inline constexpr int kLightmapPageSize = 512;  // largest atlas page (texels); small models use less

// The surfaces one draw covers: a list of indices (the world's visible surfaces) or a range
// (a brush entity's submodel).
struct SurfaceSelection {
    const uint32_t* indices = nullptr;
    uint32_t first = 0;
    uint32_t count = 0;
    uint32_t at(uint32_t i) const { return indices ? indices[i] : first + i; }
};

class BrushModelGpu {
  public:
    // nullptr with `error` set when the model's data cannot be used. `texture_filter` (may be
    // null): see create_brush_textures.
    static std::unique_ptr<BrushModelGpu> create(gl::ObjectTracker* tracker,
                                                 const nqr_brush_model& brush,
                                                 const uint8_t* palette_rgb, std::string& error,
                                                 const gl::RgbaFilter* texture_filter = nullptr);

    const nqr_brush_model& brush() const { return *brush_; }
    uint32_t num_surfaces() const { return static_cast<uint32_t>(surfaces_.size()); }

    // Rebuilds (in the CPU copy) the lightmaps of selected surfaces whose style values changed,
    // that dynamic lights reach now or reached at their last build.
    void rebuild_lightmaps(SurfaceSelection selection, const float* lightstyles,
                           std::span<const DynamicLight> lights);
    // Sends what the rebuilds changed since the last call. Once per frame, before the first
    // draw that reads the lightmaps: see LightmapAtlas.
    void upload_lightmaps() { atlas_.upload_dirty(); }

    // Groups the selection by the texture drawn at `time` (alternate chains when `alternate`).
    const SurfaceBatches& batch(SurfaceSelection selection, double time, bool alternate);

    GLuint vertex_array() const { return vertex_array_.id(); }
    const BrushTextureGpu& texture_slot(uint32_t slot) const { return textures_[slot]; }
    GLuint lightmap_texture() const { return atlas_.texture(); }
    const BrushSurfaceMesh& surface_mesh(uint32_t i) const { return surfaces_[i]; }

    int lightmap_rebuilds() const { return lightmap_rebuilds_; }  // counters for tests
    int lightmap_pages() const { return atlas_.pages(); }
    int lightmap_page_size() const { return atlas_.page_size(); }

  private:
    struct SurfaceLight {
        float applied_styles[kMaxLightStyles];
        bool built = false;
        bool dynamic = false;  // dynamic light was added at the last build
    };

    BrushModelGpu() = default;
    void upload_geometry(gl::ObjectTracker* tracker, const BrushMesh& mesh);
    bool surface_needs_rebuild(uint32_t surface, const float* lightstyles, bool lit_dynamically,
                               float* styles_out) const;
    void rebuild_surface(uint32_t surface, const float* styles,
                         std::span<const DynamicLight> lights, bool lit_dynamically);
    uint32_t texture_slot_for(const nqr_surface& surface, double time, bool alternate) const;

    const nqr_brush_model* brush_ = nullptr;
    gl::VertexArray vertex_array_;
    gl::Buffer vertices_, indices_;
    std::vector<BrushSurfaceMesh> surfaces_;
    std::vector<BrushTextureGpu> textures_;  // brush textures + placeholder last
    LightmapAtlas atlas_;
    std::vector<SurfaceLight> light_;
    std::vector<float> accumulator_;
    SurfaceBatches batches_;
    int lightmap_rebuilds_ = 0;
};

}  // namespace nq::npr::classic
