// startdemos, demos, stopdemo: Quake's attract loop (demo_loop.h). quake.rc ends with
// `startdemos demo1 demo2 demo3`; demos that are not here are skipped with a warning, and when
// none of the list is here the game directory's own demos loop instead, so a game started with
// no +command shows the menu over a running demo rather than over nothing.
#include <algorithm>

#include "app/sessions/session_controller.h"
#include "fs/vfs.h"

namespace nq {

namespace {

std::string without_extension(const std::string& path) {
    return path.size() > 4 && path.compare(path.size() - 4, 4, ".dem") == 0
               ? path.substr(0, path.size() - 4)
               : path;
}

}  // namespace

void SessionController::register_demo_loop_commands() {
    CommandSystem& c = context_.host->commands();
    c.add_command(
        "startdemos", [this](const CommandArgs& a) { start_demo_loop(a); },
        "startdemos <demo1> [demo2 ...]: loop these demos while no game runs");
    c.add_command(
        "demos",
        [this](const CommandArgs&) {
            if (loop_.names().empty())
                return context_.print("demos: no demo loop (see startdemos)");
            if (session_->active()) end_demo();
            play_next_loop_demo();
        },
        "demos: play the demo loop again, from its next demo");
    c.add_command(
        "stopdemo",
        [this](const CommandArgs&) {
            if (!session_->active() || session_->live()) return;
            end_demo();
        },
        "stopdemo: stop the demo being played, and the loop");
}

void SessionController::start_demo_loop(const CommandArgs& args) {
    if (args.argc() < 2) return context_.print("usage: startdemos <demo1> [demo2 ...]");
    std::vector<std::string> present;
    std::vector<std::string> absent;
    for (size_t i = 1; i < args.argc(); ++i) {
        const std::string& name = args.argv(i);
        (session_->exists(name) ? present : absent).push_back(name);
    }
    for (const std::string& name : absent)
        context_.print("startdemos: " + name + " is not here, skipped");
    if (present.empty() && context_.vfs) {
        for (const std::string& path : context_.vfs->list("", "dem")) {
            if (path.find('/') == std::string::npos) present.push_back(without_extension(path));
        }
        if (!present.empty())
            context_.print("startdemos: none of them is here; the game's own demos loop");
    }
    if (present.size() > kMaxLoopDemos) present.resize(kMaxLoopDemos);
    std::string line = std::to_string(present.size()) + " demo(s) in loop:";
    for (const std::string& name : present) line += " " + name;
    context_.print(line);
    loop_.set(std::move(present));
    // Quake starts the loop only when nothing else runs (a +map or +timedemo came first; the
    // rest of quake.rc waits for a command-line demo to end, and the loop stays off after it,
    // played or failed); -benchmark's timedemo is queued behind quake.rc and is the job.
    const bool after_command_line_demo = context_.timedemo->after_command_line_demo();
    if (!session_->active() && !context_.quitting() && !context_.options->benchmark &&
        !after_command_line_demo) {
        play_next_loop_demo();
    }
}

void SessionController::play_next_loop_demo() {
    const std::string name = loop_.next();
    if (name.empty()) return;
    if (std::string why = session_->start(name, DemoMode::Playback); !why.empty()) {
        context_.print("demos: " + why);
        return continue_demo_loop(true);
    }
    context_.show_showroom(false);
    loop_.set_playing(true);
}

// After a loop demo ended (or could not start): the next one, unless every demo of the loop
// has failed in a row, which stops the loop with one message instead of retrying forever.
void SessionController::continue_demo_loop(bool failed) {
    loop_.set_playing(false);
    if (!loop_.demo_ended(failed)) {
        return context_.print(
            "demos: no demo of the loop can play; the loop stops (`demos` tries again)");
    }
    play_next_loop_demo();
}

}  // namespace nq
