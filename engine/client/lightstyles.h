// Light styles: 64 patterns of letters, one letter per 0.1 s, 'a' = dark, 'm' = normal (1.0),
// 'z' = double brightness. A style the server never set stays at normal brightness.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

namespace nq {

inline constexpr int kMaxLightStyles = 64;
inline constexpr size_t kMaxLightStylePattern = 64;  // longer patterns are cut, as Quake does

class LightStyles {
  public:
    void clear();
    // False (and nothing set) for a style number outside 0..63.
    bool set(int style, std::string_view pattern);
    std::string_view pattern(int style) const;

    // Brightness of `style` at client time `time`: (letter - 'a') / ('m' - 'a').
    float value(int style, double time) const;
    void evaluate(double time, std::span<float, kMaxLightStyles> out) const;

  private:
    std::array<std::array<char, kMaxLightStylePattern>, kMaxLightStyles> patterns_{};
    std::array<uint8_t, kMaxLightStyles> lengths_{};
};

}  // namespace nq
