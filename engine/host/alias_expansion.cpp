#include "host/alias_expansion.h"

namespace nq {
namespace {

bool is_reference(std::string_view body, size_t pos) {
    if (body[pos] != '$' || pos + 1 >= body.size()) return false;
    char next = body[pos + 1];
    return (next >= '0' && next <= '9') || next == '*' || next == '$';
}

bool has_reference(std::string_view body) {
    for (size_t i = 0; i < body.size(); ++i) {
        if (is_reference(body, i)) return true;
    }
    return false;
}

std::string_view replacement(char code, const CommandArgs& invocation) {
    if (code == '$') return "$";
    if (code == '*') return invocation.args();
    return invocation.argv(static_cast<size_t>(code - '0'));
}

}  // namespace

std::optional<std::string> expand_alias(std::string_view body, const CommandArgs& invocation,
                                        size_t max_bytes) {
    std::string out;
    if (!has_reference(body)) {
        out.assign(body);
        if (invocation.argc() > 1) out.append(" ").append(invocation.args());
        if (out.size() > max_bytes) return std::nullopt;
        return out;
    }
    for (size_t i = 0; i < body.size(); ++i) {
        if (is_reference(body, i)) {
            out.append(replacement(body[i + 1], invocation));
            ++i;
        } else {
            out += body[i];
        }
        if (out.size() > max_bytes) return std::nullopt;  // checked as it grows: $* can explode
    }
    return out;
}

}  // namespace nq
