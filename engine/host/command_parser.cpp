#include "host/command_parser.h"

#include "host/text_util.h"

namespace nq {
namespace {

bool ends_quoted_token(char c) {
    return c == '"' || c == '\n' || c == '\r';
}

bool ends_word(char c) {
    return is_command_space(c) || c == '\n' || c == ';';
}

bool starts_comment(std::string_view text, size_t pos) {
    return pos + 1 < text.size() && text[pos] == '/' && text[pos + 1] == '/';
}

// Reads the token starting at `pos` (not a space, separator or comment) and returns the
// position just after it.
size_t read_token(std::string_view text, size_t pos, std::string& token) {
    if (text[pos] == '"') {
        size_t begin = pos + 1;
        size_t end = begin;
        while (end < text.size() && !ends_quoted_token(text[end])) ++end;
        token.assign(text.substr(begin, end - begin));
        return (end < text.size() && text[end] == '"') ? end + 1 : end;
    }
    size_t end = pos;
    while (end < text.size() && !ends_word(text[end])) ++end;
    token.assign(text.substr(pos, end - pos));
    return end;
}

}  // namespace

ParsedCommand parse_next_command(std::string_view text) {
    std::vector<std::string> tokens;
    std::vector<size_t> starts;
    size_t text_end = 0;  // end of the last token: the command's raw text is [first start, here)
    size_t pos = 0;
    while (true) {
        while (pos < text.size() && is_command_space(text[pos])) ++pos;
        if (pos >= text.size()) break;
        if (text[pos] == '\n' || text[pos] == ';') {
            ++pos;
            break;
        }
        if (starts_comment(text, pos)) {
            while (pos < text.size() && text[pos] != '\n') ++pos;
            continue;
        }
        starts.push_back(pos);
        tokens.emplace_back();
        pos = read_token(text, pos, tokens.back());
        text_end = pos;
    }
    ParsedCommand out;
    out.consumed = pos;
    if (tokens.empty()) return out;
    size_t first = starts.front();
    for (size_t& start : starts) start -= first;
    out.args = CommandArgs(std::move(tokens), std::string(text.substr(first, text_end - first)),
                           std::move(starts));
    return out;
}

std::vector<CommandArgs> parse_commands(std::string_view text) {
    std::vector<CommandArgs> out;
    while (!text.empty()) {
        ParsedCommand parsed = parse_next_command(text);
        if (!parsed.args.empty()) out.push_back(std::move(parsed.args));
        text.remove_prefix(parsed.consumed);
    }
    return out;
}

std::string quote_if_needed(std::string_view token) {
    std::string text(token);
    for (char& c : text) {
        if (c == '\n' || c == '\r') c = ' ';  // a line break would end the command
    }
    if (text.find('"') != std::string::npos) return text;
    bool needs_quotes = text.empty() || text.starts_with("//");
    for (char c : text) {
        if (is_command_space(c) || c == ';') needs_quotes = true;
    }
    return needs_quotes ? "\"" + text + "\"" : text;
}

}  // namespace nq
