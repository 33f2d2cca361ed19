#include "host/command_buffer.h"

#include "host/command_parser.h"

namespace nq {

bool CommandBuffer::fits(std::string_view text) const {
    return text.size() + 1 <= max_bytes_ && size() <= max_bytes_ - text.size() - 1;
}

bool CommandBuffer::add(std::string_view text) {
    if (!fits(text)) return false;
    compact();
    text_.append(text);
    if (!text.ends_with('\n')) text_ += '\n';
    return true;
}

bool CommandBuffer::insert(std::string_view text) {
    if (!fits(text)) return false;
    compact();
    std::string block(text);
    if (!block.ends_with('\n')) block += '\n';
    text_.insert(head_, block);
    return true;
}

std::optional<CommandArgs> CommandBuffer::next() {
    while (head_ < text_.size()) {
        ParsedCommand parsed = parse_next_command(pending());
        head_ += parsed.consumed;
        if (!parsed.args.empty()) return std::move(parsed.args);
    }
    clear();
    return std::nullopt;
}

void CommandBuffer::clear() {
    text_.clear();
    head_ = 0;
}

void CommandBuffer::compact() {
    if (head_ == 0) return;
    text_.erase(0, head_);
    head_ = 0;
}

}  // namespace nq
