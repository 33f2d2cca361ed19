#include "host/command_args.h"

#include "host/command_parser.h"

namespace nq {

CommandArgs::CommandArgs(std::vector<std::string> tokens, std::string text,
                         std::vector<size_t> starts)
    : tokens_(std::move(tokens)), text_(std::move(text)), starts_(std::move(starts)) {}

CommandArgs CommandArgs::from_tokens(std::vector<std::string> tokens) {
    std::string text;
    std::vector<size_t> starts;
    for (const std::string& token : tokens) {
        if (!text.empty()) text += ' ';
        starts.push_back(text.size());
        text += quote_if_needed(token);
    }
    return CommandArgs(std::move(tokens), std::move(text), std::move(starts));
}

const std::string& CommandArgs::argv(size_t i) const {
    static const std::string kEmpty;
    return i < tokens_.size() ? tokens_[i] : kEmpty;
}

std::string_view CommandArgs::rest(size_t first) const {
    if (first >= starts_.size()) return {};
    return std::string_view(text_).substr(starts_[first]);
}

std::string CommandArgs::value_from(size_t index) const {
    if (index + 1 == argc()) return argv(index);
    return std::string(rest(index));
}

}  // namespace nq
