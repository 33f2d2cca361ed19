// Draws brush surfaces the GLQuake way: the world's visible surfaces and brush entities, batched
// by texture (animated by time, alternate chains for entities with frame != 0), lightmapped with
// per-frame light styles and dynamic lights, fullbright pixels unlit, a two-layer scrolling sky
// and warped, unlit liquids; back faces culled. Order within one call: lit and fence surfaces, sky,
// then liquids (blended afterwards when water_alpha < 1).
#pragma once

#include <array>
#include <span>
#include <string>

#include <glm/mat4x4.hpp>

#include "abi/frame_view.h"
#include "classic/brush_model_gpu.h"
#include "classic/brush_programs.h"
#include "classic/lightmap_builder.h"
#include "classic/model_registry.h"
#include "nqr_renderer.h"

namespace nq::npr::classic {

inline constexpr size_t kMaxDynamicLights = 64;  // more in a frame are ignored

struct BrushSettings {
    // QuakeSpasm's gl_overbright 1 (its default): lightmaps hold half the light and are doubled
    // when drawn, so surfaces can be lit up to 2x their texture colour. 1 = GLQuake's clamp at 1.
    float overbright = 2.0f;
    float water_alpha = 1.0f;  // r_wateralpha (default 1: opaque)
};

class WorldDrawer {
  public:
    bool init(gl::ObjectTracker* tracker, std::string& error);
    void reset();

    // frame->visible_surfaces of the world model (all of its surfaces when the list is NULL).
    void draw_world(const nqr_frame& frame, const ModelRegistry& models);
    void draw_brush_entities(const nqr_frame& frame, const ModelRegistry& models);

    // One selection of a brush model placed by `model_matrix`, with the lightmaps as the frame's
    // prepare_lightmaps left them.
    void draw_selection(const nqr_frame& frame, const FrameView& view, BrushModelGpu& model,
                        SurfaceSelection selection, const glm::mat4& model_matrix,
                        bool alternate_animation, float alpha);

    BrushSettings settings;

    // Rebuilds the lightmaps the frame changes (the world's visible surfaces when `with_world`,
    // every brush entity in view; dynamic lights moved into each model's space), then uploads
    // them, before anything is drawn with them. draw_world does it for both passes.
    void prepare_lightmaps(const nqr_frame& frame, const ModelRegistry& models, bool with_world);

  private:
    static const RegisteredModel* world_selection(const nqr_frame& frame,
                                                  const ModelRegistry& models,
                                                  SurfaceSelection& selection);
    template <typename Visit>
    static void for_each_brush_entity(const nqr_frame& frame, const ModelRegistry& models,
                                      Visit&& visit);
    std::span<const DynamicLight> gather_lights(const nqr_frame& frame,
                                                const glm::mat4& model_matrix);
    void draw_batches(const nqr_frame& frame, const FrameView& view, BrushModelGpu& model,
                      const SurfaceBatches& batches, const glm::mat4& model_matrix, float alpha);
    void draw_kind(BrushModelGpu& model, const SurfaceBatches& batches, SurfaceKind kind,
                   gl::Program& program);
    void set_common_uniforms(gl::Program& program, const FrameView& view,
                             const glm::mat4& model_matrix);

    BrushPrograms programs_;
    gl::Texture black_;  // bound where a texture has no fullbright pixel
    std::array<DynamicLight, kMaxDynamicLights> lights_{};
    // draw_world prepared the brush entities' lightmaps of this frame number too.
    uint64_t entities_prepared_for_ = 0;
    bool entities_prepared_ = false;
};

}  // namespace nq::npr::classic
