// The drop-down console as the engine uses it: the scrollback, the input line, key routing
// (console keys to the input line when open, everything else to the key bindings), the
// centre-screen message, the slide animation and the console's cvars and commands.
//
//   HostCore host;
//   Console console(host);
//   host.set_print([&](std::string_view t) { console.print(t); /* and stdout */ });
//   console.set_screen_size(window.drawable_width(), window.drawable_height());
//   every frame:
//     while (window.poll_event(event)) console.handle_event(event);
//     window.set_text_input(console.is_open());
//     host.commands().execute();
//     console.update(seconds_since_start);
//     ... render the world ...
//     drawer.draw(console);   // ConsoleDrawer, console_drawer.h
//
// Registers the commands "toggleconsole" and "clear" (removed again when it goes; a name
// already taken is left to its owner) and the cvars of console_cvars.h. Destroy it before the
// HostCore. ESCAPE toggles the console too (there is no menu); an engine that wants ESCAPE for
// something else handles it before handle_event().
#pragma once

#include <string_view>

#include "console/center_print.h"
#include "console/console_cvars.h"
#include "console/console_input.h"
#include "console/console_layout.h"
#include "console/console_text.h"
#include "console/key_dispatch.h"
#include "host/host_core.h"
#include "video/input_event.h"

namespace nq {

// Quake's console covers half the screen when toggled down.
inline constexpr float kOpenConsoleFraction = 0.5f;

class Console {
  public:
    explicit Console(HostCore& host);
    ~Console();
    Console(const Console&) = delete;
    Console& operator=(const Console&) = delete;

    // Output, stamped with the clock of the latest update().
    void print(std::string_view text);
    void center_print(std::string_view text);

    // Every event from the window: keys, text, resize, focus. Returns true when the console
    // used it (a key for the input line or the toggle, typed text while open).
    bool handle_event(const InputEvent& event);
    void set_screen_size(int width, int height);
    // Once per frame with the clock in seconds: moves the slide, follows con_scale.
    void update(double now);

    bool is_open() const { return open_; }
    void set_open(bool open);
    void toggle() { set_open(!open_); }
    // How much of the screen height it covers now (0 closed, kOpenConsoleFraction open;
    // in between while sliding), and the same in pixels.
    float height_fraction() const { return fraction_; }
    int height_pixels() const;
    double now() const { return now_; }

    const ConsoleText& text() const { return text_; }
    ConsoleText& text() { return text_; }
    const ConsoleInput& input() const { return input_; }
    ConsoleInput& input() { return input_; }
    const CenterPrint& center() const { return center_; }
    const KeyDispatch& keys() const { return keys_; }
    const ConsoleLayout& layout() const { return layout_; }
    double notify_seconds() const { return cvars_.notify_time->value(); }
    double center_seconds() const { return cvars_.center_time->value(); }

  private:
    bool handle_key(const InputEvent& event);
    void apply_layout();
    void register_commands();

    HostCore& host_;
    ConsoleCvars cvars_;
    ConsoleText text_;
    ConsoleInput input_;
    KeyDispatch keys_;
    CenterPrint center_;
    ConsoleLayout layout_;
    uint32_t scale_seen_ = 0;            // con_scale's modified_count the layout follows
    bool added_toggle_command_ = false;  // only what it added is removed again
    bool added_clear_command_ = false;
    bool open_ = false;
    float fraction_ = 0.0f;
    double now_ = 0.0;
    bool clock_started_ = false;
};

}  // namespace nq
