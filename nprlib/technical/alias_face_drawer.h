// Draws the faces of alias models (MDL) in the technical style: technical_shade() per pixel
// (shading_glsl.h: Gooch 98 cool-to-warm, splash-back, metal or classic per settings.mode, each
// combination its own program) on
// k_d = the skin's mean colour (skin_tones.h, computed on the CPU: a uniform) blended toward the
// texel by texture_blend, lit from the entity's sampled light direction. Everything else
// as the classic drawer does it: pose blending, fullbright skin pixels added unlit, holey models
// cut out, Quake's clockwise winding culled, alpha < 1 blended without depth writes, view-space
// normals written to location 1 for G-buffer consumers.
#pragma once

#include <array>
#include <string>

#include <glm/vec3.hpp>

#include "abi/frame_view.h"
#include "classic/alias_model_gpu.h"
#include "gl/program.h"
#include "nqr_renderer.h"
#include "technical/shading_glsl.h"
#include "technical/technical_settings.h"

namespace nq::npr::technical {

class AliasFaceDrawer {
  public:
    bool init(gl::ObjectTracker* tracker, std::string& error);
    void reset();

    // A pass over many entities: begin (from the classic drawers' state; program, per-frame
    // uniforms and face culling set once), draw per entity, end (restores that state). The
    // caller sets the depth range (view model) and the pass order. fullbright_texture 0: none.
    // Metal bands run across the model-space height (z). kd_average: SkinSample::average of
    // the skin drawn.
    // begin is false (and draw does nothing) when the settings' shader variant cannot be built.
    bool begin(const npr::FrameView& view, const ShadingSettings& settings);
    void draw(const npr::FrameView& view, const nqr_entity& entity,
              const classic::AliasModelGpu& model, GLuint skin_texture, GLuint fullbright_texture,
              const glm::vec3& kd_average);
    void end();

    // One entity: begin, draw, end.
    void draw_entity(const npr::FrameView& view, const nqr_entity& entity,
                     const classic::AliasModelGpu& model, GLuint skin_texture,
                     GLuint fullbright_texture, const glm::vec3& kd_average,
                     const ShadingSettings& settings);

  private:
    void set_light_direction(const nqr_entity& entity);
    // One program per shading variant (shading_glsl.h), built when first needed.
    gl::Program* build_variant(int variant, std::string& error);

    gl::ObjectTracker* tracker_ = nullptr;
    std::array<gl::Program, kShadingVariants> programs_;
    gl::Program* program_ = nullptr;  // this pass's
    gl::Texture black_;
    bool add_fullbright_ = true;  // this pass's: object ids draw flat colours only
};

}  // namespace nq::npr::technical
