// The technical-illustration style as one object (the `technical` plugin is a thin C shell
// around it): the classic drawers keep the world's textures and lightmaps, sprites and
// particles; on top of them come
//   - brush edges: silhouettes and creases of the world and brush entities (BSP shared edges);
//   - alias models: planar umbra/penumbra shadows, then Gooch / splash-back / metal faces, then
//     silhouettes and creases from recovered adjacency (or the paper's back-face lines).
// Each stage is timed as its own GPU pass ("shadows", "shading", "edges") through the engine.
// No global state; settings are read every frame (the plugin copies its cvars into them).
#pragma once

#include <string>

#include "classic/classic_renderer.h"
#include "gl/object_tracker.h"
#include "nqr_renderer.h"
#include "technical/alias_edge_drawer.h"
#include "technical/alias_face_drawer.h"
#include "technical/brush_edge_drawer.h"
#include "technical/shadow_drawer.h"
#include "technical/technical_models.h"
#include "technical/technical_settings.h"

namespace nq::npr::technical {

class TechnicalRenderer {
  public:
    TechnicalRenderer() = default;
    ~TechnicalRenderer() { shutdown(); }
    TechnicalRenderer(const TechnicalRenderer&) = delete;
    TechnicalRenderer& operator=(const TechnicalRenderer&) = delete;

    // GL current. False with `error` (also logged) when something cannot be built; everything
    // is released then.
    bool init(const nqr_engine* engine, std::string* error = nullptr);
    void shutdown();

    void register_model(const nqr_model* model);
    void release_model(nqr_model_id id);

    void draw_world(const nqr_frame* frame);
    void draw_brush_entities(const nqr_frame* frame);
    void draw_alias_entities(const nqr_frame* frame);
    void draw_sprite_entities(const nqr_frame* frame) { classic_.draw_sprite_entities(frame); }
    void draw_particles(const nqr_frame* frame) { classic_.draw_particles(frame); }

    TechnicalSettings settings;

    int live_gl_objects() const { return tracker_.total_live() + classic_.live_gl_objects(); }

  private:
    enum class AliasPass { opaque, translucent, view_model };
    struct AliasItem;  // what one alias entity needs to draw

    bool fail(const std::string& message, std::string* error);
    void log(int level, const std::string& text) const;
    void pass_begin(const char* name) const;
    void pass_end() const;
    bool find_alias(const nqr_frame& frame, const nqr_entity* entity, AliasItem& out);
    void draw_shadows(const nqr_frame& frame, const classic::FrameView& view);
    void draw_faces(const nqr_frame& frame, const classic::FrameView& view, AliasPass pass);
    void draw_alias_edges(const nqr_frame& frame, const classic::FrameView& view, AliasPass pass);
    bool edges_fully_faded(const AliasItem& item, const classic::FrameView& view) const;
    float shadow_distance_fade(float distance) const;
    void draw_brush_entity_edges(const nqr_frame& frame, const classic::FrameView& view);

    gl::ObjectTracker tracker_;  // first: outlives every GL object below
    const nqr_engine* engine_ = nullptr;
    classic::ClassicRenderer classic_;
    TechnicalModels models_;
    AliasFaceDrawer faces_;
    AliasEdgeDrawer alias_edges_;
    BrushEdgeDrawer brush_edges_;
    ShadowDrawer shadows_;
    gl::Texture black_;
    bool initialised_ = false;
};

}  // namespace nq::npr::technical
