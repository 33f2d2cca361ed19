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
#include <vector>

#include <glm/vec3.hpp>

#include "abi/frame_view.h"
#include "classic/classic_pass.h"
#include "classic/classic_renderer.h"
#include "gl/object_tracker.h"
#include "nqr_renderer.h"
#include "technical/alias_edge_drawer.h"
#include "technical/alias_face_drawer.h"
#include "technical/brush_edge_drawer.h"
#include "technical/planar_shadow.h"
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
    using AliasPass = classic::AliasPass;
    // What one alias entity needs to draw this frame.
    struct AliasItem {
        const nqr_entity* entity = nullptr;
        const classic::AliasModelGpu* gpu = nullptr;
        const classic::SkinImageGpu* image = nullptr;
        const AliasEdgeMesh* edges = nullptr;
        const SkinTones* tones = nullptr;
        SkinSample skin_sample;  // on screen only
        float radius = 0;
        bool casts_shadow = true;
        GLuint skin = 0, fullbright = 0;
        EdgeSpan edge_span;
    };

    bool fail(const std::string& message, std::string* error);
    void log(int level, const std::string& text) const;
    void pass_begin(const char* name) const;
    void pass_end() const;
    bool find_alias(const nqr_entity* entity, AliasItem& out) const;
    void gather_alias_entities(const nqr_frame& frame, const npr::FrameView& view);
    SkinSample skin_sample(const AliasItem& item) const;
    ShadowPasses shadow_passes(const AliasItem& item, const npr::FrameView& view) const;
    void draw_faces(const npr::FrameView& view, AliasPass pass);
    void draw_alias_edges(const EdgeFrameUniforms& uniforms, AliasPass pass);
    bool edges_fully_faded(const AliasItem& item, const npr::FrameView& view) const;
    float shadow_distance_fade(float distance) const;
    void draw_brush_entity_edges(const nqr_frame& frame, const npr::FrameView& view);

    gl::ObjectTracker tracker_;  // first: outlives every GL object below
    const nqr_engine* engine_ = nullptr;
    classic::ClassicRenderer classic_;
    TechnicalModels models_;
    AliasFaceDrawer faces_;
    AliasEdgeDrawer alias_edges_;
    BrushEdgeDrawer brush_edges_;
    ShadowDrawer shadows_;
    std::vector<AliasItem> items_;  // this frame's alias entities on screen
    std::vector<glm::vec3> pose_;   // scratch: one entity's blended pose
    bool initialised_ = false;
};

}  // namespace nq::npr::technical
