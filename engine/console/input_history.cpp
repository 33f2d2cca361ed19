#include "console/input_history.h"

#include <algorithm>

namespace nq {

InputHistory::InputHistory(size_t capacity) : capacity_(std::max<size_t>(capacity, 1)) {}

void InputHistory::add(std::string_view line) {
    position_.reset();
    if (line.empty() || (!entries_.empty() && entries_.back() == line)) return;
    if (entries_.size() == capacity_) entries_.pop_front();
    entries_.emplace_back(line);
}

std::optional<std::string_view> InputHistory::older(std::string_view draft) {
    if (entries_.empty()) return std::nullopt;
    if (!position_) {
        draft_.assign(draft);
        position_ = 0;
        return entry(0);
    }
    if (*position_ + 1 >= entries_.size()) return std::nullopt;
    return entry(++*position_);
}

std::optional<std::string_view> InputHistory::newer() {
    if (!position_) return std::nullopt;
    if (*position_ == 0) {
        position_.reset();
        return draft_;
    }
    return entry(--*position_);
}

}  // namespace nq
