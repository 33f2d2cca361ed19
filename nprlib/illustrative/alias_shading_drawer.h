// Draws alias models (MDL) in the illustrative style: ill_shade() per pixel (illustrative_glsl.h)
// on the skin texel, with the model's own mesh (IllustrativeModel: smooth, crease-preserving
// normals per pose, blended like positions), its skin masks and warp ramp, lit by the entity's
// ambient cube and local lights. Everything else as the classic drawer does it: pose blending,
// fullbright skin pixels added unlit, holey models cut out, Quake's clockwise winding culled,
// alpha < 1 blended without depth writes, view-space normals written to location 1.
#pragma once

#include <array>
#include <string>

#include "abi/frame_view.h"
#include "classic/alias_model_gpu.h"
#include "gl/program.h"
#include "illustrative/illustrative_glsl.h"
#include "illustrative/illustrative_model.h"
#include "illustrative/illustrative_settings.h"
#include "nqr_renderer.h"

namespace nq::npr::illustrative {

// The textures one entity is drawn with. 0 for fullbright, masks or warp: a neutral default
// (black, k_s = k_r = 1 with mid exponent, the drawer's built-in ramp).
struct AliasShadingTextures {
    GLuint skin = 0;
    GLuint fullbright = 0;
    GLuint masks = 0;
    GLuint warp = 0;
};

class AliasShadingDrawer {
  public:
    bool init(gl::ObjectTracker* tracker, std::string& error);
    void reset();

    // A pass over many entities (see technical's AliasFaceDrawer): begin sets the program,
    // per-pass uniforms and culling; draw per entity; end restores the classic state.
    // `default_warp`: the ramp for entities whose textures name none.
    bool begin(const npr::FrameView& view, const IllustrativeSettings& settings,
               GLuint default_warp);
    void draw(const npr::FrameView& view, const nqr_entity& entity,
              const classic::AliasModelGpu& gpu, const IllustrativeModel& model,
              const AliasShadingTextures& textures, const MaterialParams& material);
    void end();

  private:
    // One compiled form of the shading (illustrative_glsl.h's ShadingVariant).
    struct VariantProgram {
        gl::Program program;
        bool build_failed = false;
        unsigned pass_uniforms_set = 0;  // the pass whose uniforms it holds
    };
    bool build_variant(const ShadingVariant& variant, std::string& error);
    gl::Program& use_variant(const ShadingVariant& variant);
    void set_pass_uniforms(gl::Program& program);

    gl::ObjectTracker* tracker_ = nullptr;
    std::array<VariantProgram, kShadingVariants> variants_;
    gl::Program* current_ = nullptr;
    gl::Texture black_, neutral_masks_;
    const npr::FrameView* view_ = nullptr;            // this pass's
    const IllustrativeSettings* settings_ = nullptr;  // this pass's
    unsigned pass_ = 0;
    GLuint default_warp_ = 0;
};

}  // namespace nq::npr::illustrative
