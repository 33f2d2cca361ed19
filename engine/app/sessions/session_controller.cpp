#include "app/sessions/session_controller.h"

#include <cstdio>

#include "host/number_text.h"

namespace nq {

SessionController::SessionController(SessionContext context) : context_(std::move(context)) {
    input_ = std::make_unique<PlayerInput>(context_.host->commands());
    DemoSessionCallbacks callbacks;
    callbacks.print = context_.print;
    callbacks.center_print = context_.center_print;
    // Commands inside demos are shown, not run: a downloaded demo must not drive the console.
    // Our own game's server is trusted (QuakeC's stuffcmd: bonus flashes, cvars).
    callbacks.stuff_text = [this](std::string_view text) {
        if (session_ && session_->live()) context_.host->commands().add_text(text);
    };
    callbacks.level_unloading = context_.level_unloading;
    callbacks.level_loaded = context_.level_loaded;
    callbacks.level_restarted = context_.level_restarted;
    session_ = std::make_unique<DemoSession>(context_.vfs, std::move(callbacks));
    session_->level().set_palette(context_.palette);
    session_->set_user_dir(context_.user_game_dir);
    GameContext game;
    game.host = context_.host;
    game.session = session_.get();
    game.input = input_.get();
    game.vfs = context_.vfs;
    game.user_game_dir = context_.user_game_dir;
    game.print = context_.print;
    game.begin_game = [this](std::unique_ptr<LiveGame> g, const std::string& map) {
        begin_game(std::move(g), map);
    };
    game_ = std::make_unique<GameController>(std::move(game));
}

SessionController::~SessionController() {
    game_->stop_recording();
}

void SessionController::register_commands() {
    CommandSystem& c = context_.host->commands();
    c.add_command(
        "playdemo",
        [this](const CommandArgs& a) {
            if (a.argc() < 2) return context_.print("usage: playdemo <demo>");
            start_demo(a.argv(1), DemoMode::Playback);
        },
        "play a demo in recorded time");
    c.add_command(
        "timedemo",
        [this](const CommandArgs& a) {
            if (a.argc() < 2) return context_.print("usage: timedemo <demo>");
            start_demo(a.argv(1), DemoMode::TimeDemo);
        },
        "play a demo as fast as possible and report the frame rate");
    c.add_command(
        "stop",
        [this](const CommandArgs&) {
            if (!game_->stop_recording()) end_demo();
        },
        "stop recording a demo (or, when none is recorded, the demo being played)");
    c.add_command(
        "pause", [this](const CommandArgs& a) { pause(a); },
        "freeze the demo being played (pause [0|1]; no argument toggles)");
    c.add_command(
        "viewpos", [this](const CommandArgs&) { print_view_position(); },
        "the player's position as the last message gave it, with that message's server time");
    register_demo_loop_commands();
}

SessionFrame SessionController::run_frame(double frame_time, bool game_waits, bool console_open) {
    DemoSession& s = *session_;
    SessionFrame frame;
    // A paused demo draws the same instant again: timedemo does not count those frames.
    frame.timedemo_frame = s.active() && s.mode() == DemoMode::TimeDemo && !s.paused();
    frame.game_frame = s.live() && !s.paused();
    if (!s.active()) return frame;
    frame.ran = true;
    FrameStatus status = FrameStatus::Playing;
    if (s.live()) {
        status = game_->run_frame(game_waits ? 0.0 : frame_time, console_open);
    } else {
        status = s.frame(frame_time);
    }
    if (const DemoPlayer* player = s.player()) context_.timedemo->run_schedule(player->frames());
    if (status == FrameStatus::Ended) {
        const bool next_in_loop = loop_.playing();
        const bool failed = !s.failure().empty();
        end_demo();
        frame.timedemo_frame = false;
        if (next_in_loop && !context_.quitting()) continue_demo_loop(failed);
    }
    return frame;
}

void SessionController::frame_drawn(double seconds, const SessionFrame& frame) {
    game_->frame_drawn(seconds, frame.game_frame);
    // The attract loop (quake.rc's startdemos) is not the command line's job.
    const DemoSession& s = *session_;
    context_.timedemo->update_command_line_job(s.active() && !s.live() && !loop_.playing());
}

void SessionController::start_demo(const std::string& name, DemoMode mode) {
    context_.timedemo->demo_requested();
    std::string why = session_->start(name, mode);
    if (!why.empty()) {
        if (mode != DemoMode::TimeDemo) return context_.print(why);
        TimedemoRun run = describe_run();
        run.demo = name;
        return context_.timedemo->timedemo_failed(run, why);
    }
    context_.show_showroom(false);
    loop_.set_playing(false);  // a demo chosen by hand ends the attract loop
    // The rest of the command line ("+timedemo demo +quit") waits for the demo to end.
    context_.timedemo->demo_started();
}

void SessionController::end_demo() {
    if (!session_->active()) return;
    const bool timedemo = session_->mode() == DemoMode::TimeDemo && !session_->live();
    if (timedemo) context_.timedemo->finish_timedemo(describe_run());
    session_->stop();
    loop_.set_playing(false);
    if (!context_.vfs) context_.show_showroom(true);
    context_.timedemo->demo_ended(timedemo, context_.quitting());
}

void SessionController::begin_game(std::unique_ptr<LiveGame> game, const std::string& map) {
    if (session_->active()) end_demo();
    context_.show_showroom(false);
    session_->start_game(std::move(game), map);
}

void SessionController::pause(const CommandArgs& args) {
    if (!session_->active()) return context_.print("pause: no demo is playing");
    bool on = !session_->paused();
    if (args.argc() > 1) on = parse_number_prefix(args.argv(1)) != 0;
    session_->set_paused(on);
    context_.print(on ? "paused" : "unpaused");
}

// Quake's viewpos, from the messages themselves (not the interpolated view), so a game and
// the replay of its recording can be compared exactly: "viewpos: time T origin X Y Z".
void SessionController::print_view_position() {
    if (!session_->active()) return context_.print("viewpos: no game or demo is running");
    const ClientState& client = session_->client();
    const ClientEntity* player = client.entity(client.view_entity());
    if (!player || player->msg_time < 0) return context_.print("viewpos: no position yet");
    const Vec3& o = player->msg_origins[0];
    char line[128];
    std::snprintf(line, sizeof line, "viewpos: time %.4f origin %.3f %.3f %.3f", player->msg_time,
                  double(o[0]), double(o[1]), double(o[2]));
    context_.print(line);
}

TimedemoRun SessionController::describe_run() const {
    TimedemoRun run = context_.describe_renderer();
    run.demo = session_->name();
    run.failure = session_->failure();
    return run;
}

}  // namespace nq
