// What the console shows this frame, as quads in screen pixels (y down): no GL here, so the
// layout can be tested on its own and the drawer only uploads and draws.
//
//   console down (even partly): background, scrollback rows (with "^" markers when scrolled
//     back), the input line "]text" and a blinking cursor;
//   console up: the notify rows at the top-left and the centre-screen message.
#pragma once

#include <array>
#include <string_view>
#include <vector>

#include "console/console.h"
#include "draw2d/quad_batch.h"

namespace nq {

inline constexpr size_t kNotifyRows = 4;               // Quake's NUM_CON_TIMES
inline constexpr double kCursorBlinksPerSecond = 4.0;  // on/off flips per second

struct ConsoleStyle {
    Colour background{12, 12, 20, 215};  // dark, translucent
    Colour border{150, 110, 40, 255};    // the line along the console's bottom edge
    Colour text{255, 255, 255, 255};     // multiplies the font's own colours
    Colour cursor{230, 170, 60, 170};
};

class ConsoleScene {
  public:
    explicit ConsoleScene(ConsoleStyle style = {}) : style_(style) {}

    // Whether draw() would emit anything (false: skip the GL work entirely).
    bool has_content(const Console& console) const;
    // The console's background area, when it is down: {x, y, width, height} in pixels, where
    // y may be negative (a full-screen background slid partly off the top).
    std::array<float, 4> background_rect(const Console& console) const;

    // Emits the background as a solid quad (unless the drawer draws an image instead) and
    // everything on top of it.
    void build(const Console& console, QuadBatch& batch, bool solid_background);

  private:
    void build_panel(const Console& console, QuadBatch& batch, bool solid_background);
    void build_scrollback(const Console& console, QuadBatch& batch, int height);
    void build_input_line(const Console& console, QuadBatch& batch, int height);
    void build_notify(const Console& console, QuadBatch& batch);
    void build_center_print(const Console& console, QuadBatch& batch);
    size_t notify_rows(const Console& console,
                       std::array<std::string_view, kNotifyRows>& out) const;
    bool center_print_showing(const Console& console) const;

    ConsoleStyle style_;
    std::vector<std::string_view> rows_;  // scratch, grows with the screen, reused every frame
};

}  // namespace nq
