// The illustrative style as one object (the `illustrative` plugin is a thin C shell around it):
// Valve's TF2 shading on Quake's alias models (AliasShadingDrawer: warped half-Lambert diffuse,
// ambient cube, Phong and rim terms with skin-derived masks, smooth normals), on a world drawn by
// the classic drawers with Quake's lightmaps and, when ill_abstract is on at map load, world
// textures abstracted (texture_abstraction.h: Kuwahara, saturation, value contrast). Sprites and
// particles stay classic. The model pass is timed as the GPU pass "shading".
// No global state; settings are read every frame (the plugin's cvars write into them).
#pragma once

#include <string>
#include <vector>

#include "abi/frame_view.h"
#include "classic/classic_pass.h"
#include "classic/classic_renderer.h"
#include "gl/object_tracker.h"
#include "illustrative/alias_shading_drawer.h"
#include "illustrative/illustrative_models.h"
#include "illustrative/illustrative_settings.h"
#include "nqr_renderer.h"

namespace nq::npr::illustrative {

class IllustrativeRenderer {
  public:
    IllustrativeRenderer() = default;
    ~IllustrativeRenderer() { shutdown(); }
    IllustrativeRenderer(const IllustrativeRenderer&) = delete;
    IllustrativeRenderer& operator=(const IllustrativeRenderer&) = delete;

    // GL current. False with `error` (also logged) when something cannot be built; everything
    // is released then.
    bool init(const nqr_engine* engine, std::string* error = nullptr);
    void shutdown();

    void register_model(const nqr_model* model);
    void release_model(nqr_model_id id);

    // Once a frame before drawing: picks up a changed warp ramp setting.
    void begin_frame();
    void draw_world(const nqr_frame* frame) { classic_.draw_world(frame); }
    void draw_brush_entities(const nqr_frame* frame) { classic_.draw_brush_entities(frame); }
    void draw_alias_entities(const nqr_frame* frame);
    void draw_sprite_entities(const nqr_frame* frame) { classic_.draw_sprite_entities(frame); }
    void draw_particles(const nqr_frame* frame) { classic_.draw_particles(frame); }

    IllustrativeSettings settings;

    int live_gl_objects() const { return tracker_.total_live() + classic_.live_gl_objects(); }

  private:
    using AliasPass = classic::AliasPass;
    struct AliasItem {
        const nqr_entity* entity = nullptr;
        const classic::AliasModelGpu* gpu = nullptr;
        const IllustrativeModelData* data = nullptr;  // null: drawn by the classic drawer
        AliasShadingTextures textures;
    };

    bool fail(const std::string& message, std::string* error);
    void log(int level, const std::string& text) const;
    std::optional<std::vector<uint8_t>> read_file(const std::string& path) const;
    void load_warp_ramp();
    void abstract_world_texture(int width, int height, std::vector<uint8_t>& rgba) const;
    bool gather(const nqr_frame& frame, const nqr_entity* entity, AliasItem& out);
    void draw_pass(const nqr_frame& frame, const npr::FrameView& view, AliasPass pass);

    gl::ObjectTracker tracker_;  // first: outlives every GL object below
    const nqr_engine* engine_ = nullptr;
    classic::ClassicRenderer classic_;
    IllustrativeModels models_;
    AliasShadingDrawer drawer_;
    gl::Texture warp_;
    std::string warp_name_;  // what warp_ was loaded from
    std::vector<AliasItem> items_;
    bool initialised_ = false;
};

}  // namespace nq::npr::illustrative
