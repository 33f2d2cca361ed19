#include "host/text_util.h"

namespace nq {
namespace {

constexpr size_t kMaxNameLength = 64;

char lower(char c) {
    return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
}

}  // namespace

std::string to_lower_ascii(std::string_view text) {
    std::string out(text);
    for (char& c : out) c = lower(c);
    return out;
}

bool iequals(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i) {
        if (lower(a[i]) != lower(b[i])) return false;
    }
    return true;
}

bool istarts_with(std::string_view text, std::string_view prefix) {
    return text.size() >= prefix.size() && iequals(text.substr(0, prefix.size()), prefix);
}

bool is_command_space(char c) {
    return c != '\n' && static_cast<unsigned char>(c) <= ' ';
}

bool is_valid_name(std::string_view name) {
    if (name.empty() || name.size() > kMaxNameLength) return false;
    if (name.starts_with("//")) return false;
    for (char c : name) {
        auto u = static_cast<unsigned char>(c);
        if (u <= ' ' || u >= 127 || c == '"' || c == ';') return false;
    }
    return true;
}

std::string count_noun(size_t count, std::string_view singular) {
    std::string out = std::to_string(count) + " " + std::string(singular);
    if (count != 1) out += singular.ends_with('s') ? "es" : "s";
    return out;
}

}  // namespace nq
