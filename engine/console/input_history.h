// Lines entered at the console, recalled with UPARROW / DOWNARROW. Browsing starts from what is
// being typed (the draft) and stepping past the newest entry brings the draft back.
#pragma once

#include <cstddef>
#include <deque>
#include <optional>
#include <string>
#include <string_view>

namespace nq {

inline constexpr size_t kDefaultHistoryLines = 64;

class InputHistory {
  public:
    explicit InputHistory(size_t capacity = kDefaultHistoryLines);

    // Records an entered line (empty lines and a repeat of the newest entry are not kept;
    // the oldest entry goes when full) and ends browsing.
    void add(std::string_view line);

    // The next older entry, or nullopt at the oldest. The first step saves `draft`.
    std::optional<std::string_view> older(std::string_view draft);
    // The next newer entry; past the newest, the saved draft (once); nullopt when not browsing.
    std::optional<std::string_view> newer();
    void stop_browsing() { position_.reset(); }

    size_t size() const { return entries_.size(); }
    std::string_view entry(size_t age) const { return entries_[entries_.size() - 1 - age]; }

  private:
    std::deque<std::string> entries_;  // oldest first
    size_t capacity_;
    std::optional<size_t> position_;  // age of the entry shown; unset when not browsing
    std::string draft_;
};

}  // namespace nq
