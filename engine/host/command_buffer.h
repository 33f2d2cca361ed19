// The command buffer: text waiting to be executed, consumed one command at a time.
// `add` appends (console input, bindings, startup), `insert` puts text in front of what is
// pending (alias bodies, exec'd files, so that they run before the rest of the line).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "host/command_args.h"

namespace nq {

// Bounds the buffer so that runaway scripts cannot exhaust memory; far above any real config.
inline constexpr size_t kDefaultCommandBufferBytes = 256 * 1024;

class CommandBuffer {
  public:
    explicit CommandBuffer(size_t max_bytes = kDefaultCommandBufferBytes) : max_bytes_(max_bytes) {}

    // Each call adds at least one whole command: a line break is added when `text` does not
    // end with one, so that it never runs together with the text next to it.
    // False, and nothing added, when the buffer would grow beyond its limit.
    bool add(std::string_view text);
    bool insert(std::string_view text);

    // The next non-empty command, removed from the buffer; nullopt when none is left.
    std::optional<CommandArgs> next();

    void clear();
    bool empty() const { return pending().empty(); }
    size_t size() const { return text_.size() - head_; }
    size_t max_bytes() const { return max_bytes_; }
    std::string_view pending() const { return std::string_view(text_).substr(head_); }

  private:
    bool fits(std::string_view text) const;
    void compact();

    std::string text_;
    size_t head_ = 0;  // text_[0, head_) is already consumed (erasing it each time is quadratic)
    size_t max_bytes_;
};

}  // namespace nq
