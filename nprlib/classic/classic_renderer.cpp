#include "classic/classic_renderer.h"

#include <algorithm>

#include "abi/abi_access.h"

namespace nq::npr::classic {

void ClassicRenderer::log(int level, const std::string& text) const {
    if (engine_ && engine_->log) engine_->log(engine_->context, level, text.c_str());
}

bool ClassicRenderer::fail(const std::string& message, std::string* error) {
    log(NQR_LOG_ERROR, "classic renderer: " + message);
    if (error) *error = message;
    shutdown();
    return false;
}

bool ClassicRenderer::init(const nqr_engine* engine, std::string* error) {
    shutdown();
    if (!has_known_prefix(engine)) return fail("engine services struct missing or too old", error);
    engine_ = engine;
    if (!engine->palette) return fail("the engine has no palette", error);
    std::copy(engine->palette, engine->palette + palette_.size(), palette_.begin());
    models_.init(&tracker_, palette_.data());
    std::string message;
    if (!world_.init(&tracker_, message) || !alias_.init(&tracker_, palette_.data(), message) ||
        !sprites_.init(&tracker_, message) ||
        !particles_.init(&tracker_, palette_.data(), message)) {
        return fail(message, error);
    }
    initialised_ = true;
    return true;
}

void ClassicRenderer::shutdown() {
    models_.clear();
    particles_.reset();
    sprites_.reset();
    alias_.reset();
    world_.reset();
    initialised_ = false;
}

void ClassicRenderer::register_model(const nqr_model* model) {
    if (!initialised_ || !model) return;
    alias_.forget_model(model->id);  // a re-registered id may be another model
    std::string error;
    if (!models_.add(*model, error)) {
        log(NQR_LOG_WARNING, std::string("classic renderer: model ") +
                                 (model->name ? model->name : "?") + " skipped: " + error);
    }
}

void ClassicRenderer::release_model(nqr_model_id id) {
    alias_.forget_model(id);
    models_.remove(id);
}

bool ClassicRenderer::frame_usable(const nqr_frame* frame) {
    return frame_readable(frame);
}

void ClassicRenderer::draw_world(const nqr_frame* frame) {
    if (initialised_ && frame_usable(frame)) world_.draw_world(*frame, models_);
}

void ClassicRenderer::draw_brush_entities(const nqr_frame* frame) {
    if (initialised_ && frame_usable(frame)) world_.draw_brush_entities(*frame, models_);
}

void ClassicRenderer::draw_alias_entities(const nqr_frame* frame) {
    if (initialised_ && frame_usable(frame)) alias_.draw_alias_entities(*frame, models_);
}

void ClassicRenderer::draw_sprite_entities(const nqr_frame* frame) {
    if (initialised_ && frame_usable(frame)) sprites_.draw_sprite_entities(*frame, models_);
}

void ClassicRenderer::draw_particles(const nqr_frame* frame) {
    if (initialised_ && frame_usable(frame)) particles_.draw_particles(*frame);
}

}  // namespace nq::npr::classic
