#include "support/json_checks.h"

#include <vector>

namespace nq::test {

bool looks_like_json_object(const std::string& text) {
    std::vector<char> open;
    bool in_string = false;
    const size_t first = text.find_first_not_of(" \n");
    if (first == std::string::npos || text[first] != '{') return false;
    for (size_t i = first; i < text.size(); ++i) {
        const char c = text[i];
        if (in_string) {
            if (static_cast<unsigned char>(c) < 0x20) return false;
            if (c == '\\') ++i;  // skip the escaped character
            if (c == '"') in_string = false;
            continue;
        }
        if (c == '"') {
            in_string = true;
        } else if (c == '{' || c == '[') {
            open.push_back(c);
        } else if (c == '}' || c == ']') {
            if (open.empty() || open.back() != (c == '}' ? '{' : '[')) return false;
            open.pop_back();
            if (open.empty()) return text.find_first_not_of(" \n", i + 1) == std::string::npos;
        }
    }
    return false;
}

}  // namespace nq::test
