// Numbers in cvar strings: parsed and printed the same way whatever the C locale says.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace nq {

// Quake's atof rule: the number at the start of the text (after spaces), 0 when there is none.
// "1.5abc" -> 1.5, "abc" -> 0. NaN is read as 0 so that no cvar ever holds NaN.
float parse_number_prefix(std::string_view text);

// The whole text (spaces around it allowed) must be one number; NaN is refused.
std::optional<float> parse_number_exact(std::string_view text);

// Shortest text that reads back as the same float: 1 -> "1", 0.5 -> "0.5".
std::string format_number(float value);

// (int)value without undefined behaviour: truncates toward zero, saturates at the int32
// limits, NaN -> 0.
int32_t saturating_int(float value);

}  // namespace nq
