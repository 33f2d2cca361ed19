#include "hud/big_numbers.h"

#include <algorithm>
#include <array>
#include <charconv>

namespace nq {

size_t big_number_characters(int64_t value, int digits, std::span<char> out) {
    std::array<char, 24> text{};
    auto [end, error] = std::to_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc{}) return 0;
    size_t length = static_cast<size_t>(end - text.data());
    size_t shown = std::min({length, static_cast<size_t>(std::max(digits, 0)), out.size()});
    std::copy(end - shown, end, out.begin());
    return shown;
}

void draw_big_number(const HudCanvas& canvas, float x, float y, int64_t value, int digits,
                     int colour) {
    std::array<char, 24> characters{};
    size_t shown = big_number_characters(value, digits, characters);
    const auto& pictures = canvas.pictures().ids().numbers[colour == kRedNumbers ? 1 : 0];
    x += static_cast<float>((digits - static_cast<int>(shown)) * kBigDigitWidth);
    for (size_t i = 0; i < shown; ++i, x += kBigDigitWidth) {
        char c = characters[i];
        canvas.picture(c == '-' ? pictures[kMinusDigit] : pictures[c - '0'], x, y);
    }
}

}  // namespace nq
