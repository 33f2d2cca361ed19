#include "console/console.h"

#include <algorithm>

#include "console/console_keys.h"

namespace nq {
namespace {

// scr_conspeed counts lines of Quake's 200-line screen.
constexpr float kSpeedReferenceLines = 200.0f;

}  // namespace

Console::Console(HostCore& host)
    : host_(host),
      cvars_(register_console_cvars(host.cvars())),
      input_(host.commands(), text_),
      keys_(host.commands(), host.bindings()),
      layout_(make_console_layout(kReferenceScreenWidth, kReferenceScreenHeight, 0)) {
    register_commands();
    apply_layout();
}

Console::~Console() {
    if (added_toggle_command_) host_.commands().remove_command("toggleconsole");
    if (added_clear_command_) host_.commands().remove_command("clear");
}

void Console::register_commands() {
    CommandSystem& commands = host_.commands();
    added_toggle_command_ = commands.add_command(
        "toggleconsole", [this](const CommandArgs&) { toggle(); },
        "toggleconsole: open or close the console");
    added_clear_command_ = commands.add_command(
        "clear", [this](const CommandArgs&) { text_.clear(); },
        "clear: empty the console's scrollback");
}

void Console::print(std::string_view text) {
    text_.print(text, now_);
}

void Console::center_print(std::string_view text) {
    center_.show(text, now_);
}

void Console::set_open(bool open) {
    if (open == open_) return;
    open_ = open;
    text_.clear_notify();  // what was printed meanwhile was seen in the console
}

int Console::height_pixels() const {
    return static_cast<int>(fraction_ * static_cast<float>(layout_.screen_height));
}

void Console::set_screen_size(int width, int height) {
    layout_.screen_width = width;
    layout_.screen_height = height;
    apply_layout();
}

void Console::apply_layout() {
    scale_seen_ = cvars_.scale->modified_count();
    layout_ =
        make_console_layout(layout_.screen_width, layout_.screen_height, cvars_.scale->integer());
    if (text_.columns() != layout_.columns) text_.set_columns(layout_.columns);
}

void Console::update(double now) {
    double elapsed = clock_started_ ? std::max(now - now_, 0.0) : 0.0;
    now_ = now;
    clock_started_ = true;
    if (cvars_.scale->modified_count() != scale_seen_) apply_layout();

    float target = open_ ? kOpenConsoleFraction : 0.0f;
    float speed = cvars_.slide_speed->value() / kSpeedReferenceLines;  // screens per second
    if (speed <= 0.0f) {
        fraction_ = target;
        return;
    }
    float step = speed * static_cast<float>(elapsed);
    fraction_ = fraction_ < target ? std::min(fraction_ + step, target)
                                   : std::max(fraction_ - step, target);
}

bool Console::handle_event(const InputEvent& event) {
    switch (event.type) {
        case InputEventType::Key:
            return event.key != nullptr && handle_key(event);
        case InputEventType::Text:
            if (!open_) return false;
            input_.text_input(event.text.data());
            return true;
        case InputEventType::Resize:
            set_screen_size(event.width, event.height);
            return false;
        case InputEventType::FocusLost:
            keys_.release_all();
            return false;
        default:
            return false;
    }
}

bool Console::handle_key(const InputEvent& event) {
    std::string_view key = event.key;
    if (!event.down) {
        keys_.key_up(key);  // ends a '+' action even if the console opened meanwhile
        if (open_ && is_console_key(key)) input_.key_up(key);
        return open_ && is_console_key(key);
    }
    if ((key == kConsoleToggleKey || key == "ESCAPE") && !event.repeat) {
        toggle();
        return true;
    }
    if (open_ && is_console_key(key)) return input_.key_down(key);
    keys_.key_down(key, event.repeat);
    return false;
}

}  // namespace nq
