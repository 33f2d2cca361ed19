#include "host/number_text.h"

#include <charconv>
#include <cmath>
#include <limits>

#include "host/text_util.h"

namespace nq {
namespace {

std::string_view trim_front(std::string_view text) {
    while (!text.empty() && (is_command_space(text.front()) || text.front() == '\n')) {
        text.remove_prefix(1);
    }
    return text;
}

std::string_view trim_back(std::string_view text) {
    while (!text.empty() && (is_command_space(text.back()) || text.back() == '\n')) {
        text.remove_suffix(1);
    }
    return text;
}

// std::from_chars takes '-' but not '+'; accept "+5" like atof does.
std::string_view skip_plus(std::string_view text) {
    if (text.size() >= 2 && text[0] == '+' && text[1] != '-' && text[1] != '+') {
        text.remove_prefix(1);
    }
    return text;
}

// A number beyond even double's range: infinite when its magnitude is huge, 0 when tiny.
double out_of_range_value(std::string_view number) {
    bool negative = number.starts_with('-');
    size_t exponent = number.find_first_of("eE");
    bool tiny = exponent != std::string_view::npos
                    ? number.substr(exponent + 1).starts_with('-')
                    : number.find_first_not_of("-0.") == std::string_view::npos ||
                          number.find_first_not_of("-0") == number.find('.');
    if (tiny) return negative ? -0.0 : 0.0;
    return negative ? -HUGE_VAL : HUGE_VAL;
}

// Parses the longest number at the start of `text` as a double; `used` gets its length
// (0 when there is none).
double read_double(std::string_view text, size_t& used) {
    double value = 0.0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    used = static_cast<size_t>(end - text.data());
    if (ec == std::errc::result_out_of_range) return out_of_range_value(text.substr(0, used));
    if (ec != std::errc()) used = 0;
    return ec == std::errc() ? value : 0.0;
}

// double -> float without the undefined behaviour of converting an out-of-range value.
float to_float(double value) {
    if (std::isnan(value)) return 0.0f;
    if (value > std::numeric_limits<float>::max()) return std::numeric_limits<float>::infinity();
    if (value < -std::numeric_limits<float>::max()) return -std::numeric_limits<float>::infinity();
    return static_cast<float>(value);
}

}  // namespace

float parse_number_prefix(std::string_view text) {
    size_t used = 0;
    return to_float(read_double(skip_plus(trim_front(text)), used));
}

std::optional<float> parse_number_exact(std::string_view text) {
    text = skip_plus(trim_back(trim_front(text)));
    size_t used = 0;
    double value = read_double(text, used);
    if (used == 0 || used != text.size() || std::isnan(value)) return std::nullopt;
    return to_float(value);
}

std::string format_number(float value) {
    if (value == 0.0f) return "0";  // also turns -0 into "0"
    char buffer[64];
    auto [end, ec] = std::to_chars(buffer, buffer + sizeof(buffer), value);
    if (ec != std::errc()) return "0";
    return std::string(buffer, end);
}

int32_t saturating_int(float value) {
    if (std::isnan(value)) return 0;
    // 2^31 is exactly representable as a float; anything at or above it saturates.
    if (value >= 2147483648.0f) return std::numeric_limits<int32_t>::max();
    if (value <= -2147483648.0f) return std::numeric_limits<int32_t>::min();
    return static_cast<int32_t>(value);
}

}  // namespace nq
