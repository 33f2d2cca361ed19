// Which models the renderer holds: a demo's level or the showroom, never both.
#include "app/engine.h"

#include <epoxy/gl.h>

namespace nq {

void Engine::register_level_models(Level& level) {
    show_showroom(false);
    scene_.bind_level(level);
    for (const auto& model : level.models().models()) dispatch_->register_model(model->abi());
    level_models_registered_ = true;
    warm_up_renderer(level);
    view_state_ = {};
    if (const Cvar* developer = host_.cvars().find("developer"); developer && developer->value()) {
        const AmbientCubeField* field = level.ambient_field();
        print("ambient cube field: " + std::to_string(field ? field->samples().size() : 0) +
              " samples baked in " + std::to_string(int(level.ambient_bake_seconds() * 1000.0)) +
              " ms");
    }
}

void Engine::warm_up_renderer(Level& level) {
    if (!level.loaded()) return;
    CameraSetup camera;
    camera.fov_x = cvars_.fov->value();
    camera.viewport[2] = window_->drawable_width();
    camera.viewport[3] = window_->drawable_height();
    glViewport(0, 0, camera.viewport[2], camera.viewport[3]);
    dispatch_->set_obscurance(obscurance_cvars_.settings());
    dispatch_->draw(scene_.build_warm_up(level, camera));
    glFinish();
}

// The renderer keeps the models it has; only what belongs to the view starts afresh.
void Engine::level_restarted(Level& level) {
    if (!level_models_registered_) return register_level_models(level);
    view_state_ = {};
    if (const Cvar* developer = host_.cvars().find("developer"); developer && developer->value()) {
        print("map restarted: the level and its " + std::to_string(level.models().models().size()) +
              " models kept");
    }
}

void Engine::release_level_models() {
    if (!level_models_registered_) return;
    dispatch_->clear_models();
    level_models_registered_ = false;
}

void Engine::show_showroom(bool on) {
    if (on == (showroom_ != nullptr)) return;
    if (on) {
        release_level_models();
        showroom_ = std::make_unique<Showroom>();
        showroom_->assign_ids(1);
        for (const nqr_model* m : showroom_->models()) dispatch_->register_model(m);
    } else {
        dispatch_->clear_models();
        showroom_.reset();
    }
}

}  // namespace nq
