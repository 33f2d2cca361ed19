// QuakeC strings: a string value is an int32. Values 0..size-1 index the progs' own string table;
// negative values name strings the engine made: a ring of temporary strings (what ftos, vtos and
// etos return; each call reuses the oldest of 16 fixed buffers, as QuakeSpasm does, so nothing is
// allocated per frame) and strings kept until the next level (the entity lump's values, map names).
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace nq::vm {

class StringTable {
  public:
    static constexpr int kTempStrings = 16;
    static constexpr size_t kTempLength = 1024;  // bytes per temporary string, NUL included

    explicit StringTable(const std::vector<char>& progs_strings) : progs_(progs_strings) {}

    // The string `value` names, or nothing when it names none.
    std::optional<std::string_view> get(int32_t value) const;

    // Copies `text` into the next temporary buffer (cut at kTempLength - 1 bytes).
    int32_t make_temp(std::string_view text);
    // Keeps `text` until clear_level(): for strings that outlive a call (entity fields).
    int32_t make_level(std::string_view text);
    void clear_level() { level_.clear(); }

    // Whether `value` is one of the temporary buffers (a saved game must not keep it).
    static bool is_temp(int32_t value) { return value < 0 && value >= -kTempStrings; }

  private:
    const std::vector<char>& progs_;
    std::array<std::array<char, kTempLength>, kTempStrings> temp_{};
    std::array<uint32_t, kTempStrings> temp_length_{};
    int next_temp_ = 0;
    std::deque<std::string> level_;  // deque: references stay valid as it grows
};

}  // namespace nq::vm
