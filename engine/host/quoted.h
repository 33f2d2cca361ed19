// Console text in double quotes, as Quake prints names and values ("bind" "+forward").
#pragma once

#include <string>
#include <string_view>

namespace nq {

// Built by appending: GCC 12 warns (-Wrestrict, a false positive) on "\"" + std::string(...)
// at -O2.
inline std::string quoted(std::string_view text) {
    std::string out;
    out.reserve(text.size() + 2);
    out.push_back('"');
    out.append(text);
    out.push_back('"');
    return out;
}

}  // namespace nq
