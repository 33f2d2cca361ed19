#include "host/cvar.h"

#include "host/number_text.h"

namespace nq {

void Cvar::store(std::string text) {
    string_ = std::move(text);
    view_.value = parse_number_prefix(string_);
    view_.integer = saturating_int(view_.value);
    view_.string =
        string_.c_str();  // the node never moves, so this stays valid until the next store
}

std::string describe_range(const Cvar& cvar) {
    auto lo = cvar.min_value();
    auto hi = cvar.max_value();
    if (lo && hi) return "between " + format_number(*lo) + " and " + format_number(*hi);
    if (lo) return "of at least " + format_number(*lo);
    if (hi) return "of at most " + format_number(*hi);
    return "";
}

}  // namespace nq
