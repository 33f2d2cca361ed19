// Draws alias models (MDL) the GLQuake way, with QuakeSpasm's pose interpolation:
//   - the vertex shader blends pose0 -> pose1 by the entity's lerp (positions and normals);
//   - shading: GLQuake lit a model with one light level and a fixed-direction table of
//     per-normal dot products, brighter on the lit side with an ambient floor. Here the same
//     shape comes from the engine's sampled light: shade = ambient + directional x
//     max(0, n . direction), tinted by the light colour; NQR_ENTITY_FULLBRIGHT draws at 1;
//   - skins with fullbright pixels added unlit; player colours (has_translation) through
//     translated skin copies;
//   - the view model (NQR_ENTITY_VIEWMODEL) last, squeezed into depth range 0..0.3 so it never
//     sinks into walls (GLQuake's hack), with GLQuake's ambient floor of 24/200;
//   - alpha < 1 blended after the opaque ones.
#pragma once

#include <cstdint>
#include <string>

#include "abi/frame_view.h"
#include "classic/classic_pass.h"
#include "classic/model_registry.h"
#include "classic/translated_skins.h"
#include "gl/program.h"
#include "nqr_renderer.h"

namespace nq::npr::classic {

struct AliasSettings {
    float view_model_depth_max = 0.3f;
    float view_model_min_ambient = 24.0f / 200.0f;
};

class AliasDrawer {
  public:
    bool init(gl::ObjectTracker* tracker, const uint8_t* palette_rgb, std::string& error);
    void reset();

    void draw_alias_entities(const nqr_frame& frame, const ModelRegistry& models);

    // One entity (depth test and range as the caller set them); used by draw_alias_entities.
    void draw_entity(const nqr_frame& frame, const FrameView& view, const nqr_entity& entity,
                     const AliasModelGpu& model);

    // The skin texture to draw `entity` with: its skin image, or a player-colour translated copy
    // (made on first use, then cached). Shared with NPR drawers that start from the skin.
    GLuint skin_texture(const nqr_frame& frame, const nqr_entity& entity,
                        const AliasModelGpu& model, const SkinImageGpu& image);

    void forget_model(nqr_model_id id) { translated_.forget_model(id); }
    const TranslatedSkins& translated_skins() const { return translated_; }

    AliasSettings settings;

  private:
    void draw_pass(const nqr_frame& frame, const FrameView& view, const ModelRegistry& models,
                   AliasPass pass);
    void set_lighting(const nqr_entity& entity);

    gl::Program program_;
    gl::Texture black_;
    TranslatedSkins translated_;
};

}  // namespace nq::npr::classic
