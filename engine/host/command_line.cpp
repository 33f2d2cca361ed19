#include "host/command_line.h"

#include "host/command_parser.h"
#include "host/text_util.h"

namespace nq {
namespace {

bool is_number_start(char c) {
    return (c >= '0' && c <= '9') || c == '.';
}

bool is_flag(std::string_view token) {
    return token.size() >= 2 && token[0] == '-' && !is_number_start(token[1]);
}

bool is_command(std::string_view token) {
    return token.size() >= 2 && token[0] == '+';
}

}  // namespace

CommandLine CommandLine::parse(const std::vector<std::string>& args) {
    CommandLine line;
    bool in_command = false;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& token = args[i];
        if (is_command(token)) {
            line.commands_.push_back({token.substr(1)});
            in_command = true;
        } else if (is_flag(token)) {
            Flag flag{token, std::nullopt};
            bool has_value =
                i + 1 < args.size() && !is_flag(args[i + 1]) && !is_command(args[i + 1]);
            if (has_value) flag.value = args[++i];
            line.flags_.push_back(std::move(flag));
            in_command = false;
        } else if (in_command) {
            line.commands_.back().push_back(token);
        } else {
            line.stray_.push_back(token);
        }
    }
    return line;
}

CommandLine CommandLine::from_main(int argc, const char* const* argv) {
    std::vector<std::string> args;
    for (int i = 1; i < argc; ++i) args.emplace_back(argv[i] ? argv[i] : "");
    return parse(args);
}

const CommandLine::Flag* CommandLine::last(std::string_view flag) const {
    for (auto it = flags_.rbegin(); it != flags_.rend(); ++it) {
        if (iequals(it->name, flag)) return &*it;
    }
    return nullptr;
}

bool CommandLine::has(std::string_view flag) const {
    return last(flag) != nullptr;
}

std::optional<std::string> CommandLine::value(std::string_view flag) const {
    const Flag* found = last(flag);
    return found ? found->value : std::nullopt;
}

std::optional<size_t> CommandLine::last_position(std::string_view flag) const {
    const Flag* found = last(flag);
    if (!found) return std::nullopt;
    return static_cast<size_t>(found - flags_.data());
}

std::string CommandLine::command_text() const {
    std::string text;
    for (const auto& command : commands_) {
        for (size_t i = 0; i < command.size(); ++i) {
            if (i > 0) text += ' ';
            text += quote_if_needed(command[i]);
        }
        text += '\n';
    }
    return text;
}

}  // namespace nq
