#include "hud/hud.h"

#include "client/view_blend.h"

namespace nq {

Hud::Hud(HostCore& host) : host_(host), cvars_(register_hud_cvars(host.cvars())) {
    add_command(
        "+showscores", [this](const CommandArgs&) { show_scores_ = true; },
        "+showscores: show the scoreboard while the key is held");
    add_command(
        "-showscores", [this](const CommandArgs&) { show_scores_ = false; },
        "-showscores: back to the status bar");
    // Quake's screen-size keys (default.cfg binds + and -): viewsize in steps of 10, within
    // the cvar's 30..120.
    add_command(
        "sizeup", [this](const CommandArgs&) { step_viewsize(+kViewsizeStep); },
        "sizeup: a larger view (viewsize + 10: fewer bars)");
    add_command(
        "sizedown", [this](const CommandArgs&) { step_viewsize(-kViewsizeStep); },
        "sizedown: a smaller view (viewsize - 10: more bars)");
}

Hud::~Hud() {
    for (const std::string& name : added_commands_) host_.commands().remove_command(name);
}

void Hud::add_command(const char* name, CommandFn fn, const char* description) {
    if (host_.commands().add_command(name, std::move(fn), description)) {
        added_commands_.emplace_back(name);
    }
}

void Hud::step_viewsize(float step) {
    const float size = cvars_.viewsize->value() + step;
    host_.cvars().set("viewsize", std::to_string(static_cast<int>(size)));  // clamped to range
}

std::vector<std::string> Hud::load_pictures(const Wad* gfx_wad, const Palette* palette,
                                            const Vfs* vfs) {
    std::vector<std::string> messages;
    Result<HudDrawer> drawer = HudDrawer::create();
    if (!drawer) {
        messages.push_back("status bar: " + drawer.error().message);
        return messages;
    }
    drawer_.emplace(std::move(*drawer));
    if (!gfx_wad || !palette) return messages;  // tints only

    HudPictures pictures = HudPictures::load(*gfx_wad, *palette, vfs);
    for (const std::string& warning : pictures.warnings()) {
        messages.push_back("status bar: " + warning);
    }
    if (!pictures.missing().empty()) {
        std::string line = "pictures not in the game data, not drawn:";
        for (const std::string& name : pictures.missing()) line += " " + name;
        messages.push_back(line);
    }
    drawer_->set_pictures(std::move(pictures));
    return messages;
}

void Hud::count_frame(double real_time) {
    if (fps_since_ < 0 || real_time < fps_since_) {
        fps_since_ = real_time;
        fps_frames_ = 0;
    }
    ++fps_frames_;
    if (const double elapsed = real_time - fps_since_; elapsed >= 1.0) {
        fps_ = float(fps_frames_ / elapsed);
        fps_since_ = real_time;
        fps_frames_ = 0;
    }
}

HudSettings Hud::settings() const {
    HudSettings settings;
    settings.viewsize = cvars_.viewsize->value();
    settings.bar_alpha = cvars_.bar_alpha->value();
    settings.crosshair = cvars_.crosshair->value() != 0;
    settings.show_scores = show_scores_;
    settings.show_fps = cvars_.show_fps->value() != 0;
    return settings;
}

void Hud::draw(const ClientState& client, int eye_contents, int width, int height,
               double real_time) {
    if (!drawer_) return;
    ScreenBlend blend;
    if (cvars_.polyblend->value() != 0) blend = view_blend(client, eye_contents);
    HudFrame frame;
    frame.screen = HudScreen{width, height, cvars_.bar_scale->value()};
    frame.settings = settings();
    frame.real_time = real_time;
    frame.fps = fps_;
    drawer_->draw(client, blend, frame, cvars_.draw_hud->value() != 0);
}

}  // namespace nq
