// The centre-screen message (Quake's centerprint: "The door is locked", level titles). It shows
// for a few seconds, split into lines at '\n' and every 40 characters, each line centred.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <string_view>

namespace nq {

inline constexpr size_t kCenterPrintLineWidth = 40;  // Quake's limit per centred line
inline constexpr double kDefaultCenterPrintSeconds = 2.0;

class CenterPrint {
  public:
    // Replaces any message on screen; it shows from `now` (seconds).
    void show(std::string_view text, double now);
    void clear() { text_.clear(); }

    const std::string& text() const { return text_; }
    // True within `seconds` after show() (and never for an empty message).
    bool visible(double now, double seconds) const;
    // Number of lines the message takes (0 when empty).
    size_t line_count() const;
    // Its lines, top first, at most out.size(); returns how many were filled.
    size_t lines(std::span<std::string_view> out) const;

  private:
    std::string text_;
    double shown_at_ = 0;
};

}  // namespace nq
