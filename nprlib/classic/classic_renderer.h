// The GLQuake look as one object: the default drawers the engine uses for hooks a plugin leaves
// NULL, and that a plugin can instantiate to keep the parts it does not replace. Each draw method
// mirrors an nqr_renderer hook and works on its own (a plugin that draws alias models itself
// still calls draw_world, draw_brush_entities, ...).
//
// Lifetime: init() with the GL context current (builds programs), register_model()/
// release_model() as the engine calls them, draw_*() per frame, shutdown() (also run by the
// destructor) releases every GL object; live_gl_objects() then reads 0. No global state: a
// plugin keeps its ClassicRenderer in an object it creates in init and destroys in shutdown.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "classic/alias_drawer.h"
#include "classic/model_registry.h"
#include "classic/particle_drawer.h"
#include "classic/sprite_drawer.h"
#include "classic/world_drawer.h"
#include "gl/object_tracker.h"
#include "nqr_renderer.h"

namespace nq::npr::classic {

class ClassicRenderer {
  public:
    ClassicRenderer() = default;
    ~ClassicRenderer() { shutdown(); }
    ClassicRenderer(const ClassicRenderer&) = delete;
    ClassicRenderer& operator=(const ClassicRenderer&) = delete;

    // Copies the palette, builds the shaders. False with `error` (also sent to engine->log when
    // given) when the engine lacks a palette or a shader fails; everything is released then.
    bool init(const nqr_engine* engine, std::string* error = nullptr);
    void shutdown();
    bool initialised() const { return initialised_; }

    // Unusable model data is logged (engine->log) and the model skipped.
    void register_model(const nqr_model* model);
    void release_model(nqr_model_id id);

    void draw_world(const nqr_frame* frame);
    void draw_brush_entities(const nqr_frame* frame);
    void draw_alias_entities(const nqr_frame* frame);
    void draw_sprite_entities(const nqr_frame* frame);
    void draw_particles(const nqr_frame* frame);

    // Tuning (the classic defaults are QuakeSpasm's; see BrushSettings / AliasSettings).
    BrushSettings& brush_settings() { return world_.settings; }
    AliasSettings& alias_settings() { return alias_.settings; }

    const ModelRegistry& models() const { return models_; }
    // A style's rewrite of brush textures before upload, for models registered from now on.
    void set_brush_texture_filter(gl::RgbaFilter filter) {
        models_.set_brush_texture_filter(std::move(filter));
    }
    WorldDrawer& world_drawer() { return world_; }
    AliasDrawer& alias_drawer() { return alias_; }
    SpriteDrawer& sprite_drawer() { return sprites_; }
    ParticleDrawer& particle_drawer() { return particles_; }
    const uint8_t* palette() const { return palette_.data(); }

    const gl::ObjectTracker& gl_objects() const { return tracker_; }
    int live_gl_objects() const { return tracker_.total_live(); }

  private:
    bool fail(const std::string& message, std::string* error);
    void log(int level, const std::string& text) const;
    static bool frame_usable(const nqr_frame* frame);

    gl::ObjectTracker tracker_;  // first: outlives every GL object below
    const nqr_engine* engine_ = nullptr;
    std::array<uint8_t, 768> palette_{};
    ModelRegistry models_;
    WorldDrawer world_;
    AliasDrawer alias_;
    SpriteDrawer sprites_;
    ParticleDrawer particles_;
    bool initialised_ = false;
};

}  // namespace nq::npr::classic
