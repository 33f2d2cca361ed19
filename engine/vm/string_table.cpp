#include "vm/string_table.h"

#include <algorithm>
#include <cstring>

namespace nq::vm {

std::optional<std::string_view> StringTable::get(int32_t value) const {
    if (value >= 0) {
        if (size_t(value) >= progs_.size()) return std::nullopt;
        return std::string_view(progs_.data() + value);  // the table ends with a NUL
    }
    if (is_temp(value)) {
        const int slot = -value - 1;
        return std::string_view(temp_[size_t(slot)].data(), temp_length_[size_t(slot)]);
    }
    const int64_t index = -int64_t(value) - 1 - kTempStrings;
    if (size_t(index) >= level_.size()) return std::nullopt;
    return std::string_view(level_[size_t(index)]);
}

int32_t StringTable::make_temp(std::string_view text) {
    const int slot = next_temp_;
    next_temp_ = (next_temp_ + 1) % kTempStrings;
    const size_t n = std::min(text.size(), kTempLength - 1);
    std::memcpy(temp_[size_t(slot)].data(), text.data(), n);
    temp_[size_t(slot)][n] = '\0';
    temp_length_[size_t(slot)] = uint32_t(std::strlen(temp_[size_t(slot)].data()));
    return -(slot + 1);
}

int32_t StringTable::make_level(std::string_view text) {
    // A string up to its first NUL, as QuakeC will read it.
    level_.emplace_back(text.substr(0, text.find('\0')));
    return -int32_t(level_.size()) - kTempStrings;
}

}  // namespace nq::vm
