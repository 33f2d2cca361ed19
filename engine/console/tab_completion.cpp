#include "console/tab_completion.h"

#include <algorithm>
#include <optional>

#include "host/text_util.h"

namespace nq {
namespace {

char lower_ascii(char c) {
    return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
}

struct WordSpan {
    size_t begin = 0;
    size_t end = 0;
};

// The command-name word that ends at `cursor`, or nullopt when the cursor is in an argument
// or inside a quoted string.
std::optional<WordSpan> command_word_before(std::string_view line, size_t cursor) {
    size_t start = 0;
    bool quoted = false;
    for (size_t i = 0; i < cursor; ++i) {
        if (line[i] == '"') quoted = !quoted;
        if (line[i] == ';' && !quoted) start = i + 1;
    }
    if (quoted) return std::nullopt;
    while (start < cursor && is_command_space(line[start])) ++start;
    for (size_t i = start; i < cursor; ++i) {
        if (is_command_space(line[i])) return std::nullopt;
    }
    return WordSpan{start, cursor};
}

}  // namespace

std::vector<std::string> completion_candidates(const CommandSystem& commands,
                                               std::string_view prefix) {
    std::vector<std::string> names;
    for (const CommandInfo& command : commands.list_commands(prefix)) names.push_back(command.name);
    for (const AliasInfo& alias : commands.list_aliases()) {
        if (istarts_with(alias.name, prefix)) names.push_back(alias.name);
    }
    for (const Cvar* cvar : commands.cvars().list(prefix)) names.push_back(cvar->name());

    auto lower_less = [](const std::string& a, const std::string& b) {
        return to_lower_ascii(a) < to_lower_ascii(b);
    };
    std::stable_sort(names.begin(), names.end(), lower_less);
    auto same = [](const std::string& a, const std::string& b) { return iequals(a, b); };
    names.erase(std::unique(names.begin(), names.end(), same), names.end());
    return names;
}

std::string common_prefix(const std::vector<std::string>& names) {
    if (names.empty()) return {};
    size_t length = names.front().size();
    for (const std::string& name : names) {
        size_t shared = 0;
        while (shared < length && shared < name.size() &&
               lower_ascii(name[shared]) == lower_ascii(names.front()[shared])) {
            ++shared;
        }
        length = shared;
    }
    return names.front().substr(0, length);
}

CompletionResult complete_command(const CommandSystem& commands, std::string_view line,
                                  size_t cursor) {
    cursor = std::min(cursor, line.size());
    CompletionResult result{std::string(line), cursor, {}};
    std::optional<WordSpan> word = command_word_before(line, cursor);
    if (!word || word->begin == word->end) return result;

    std::string_view prefix = line.substr(word->begin, word->end - word->begin);
    result.candidates = completion_candidates(commands, prefix);
    if (result.candidates.empty()) return result;

    std::string completed = result.candidates.size() == 1 ? result.candidates.front()
                                                          : common_prefix(result.candidates);
    bool needs_space =
        result.candidates.size() == 1 && (cursor == line.size() || !is_command_space(line[cursor]));
    if (needs_space) completed += ' ';
    result.line.replace(word->begin, word->end - word->begin, completed);
    result.cursor = word->begin + completed.size();
    if (result.candidates.size() == 1 && !needs_space) ++result.cursor;  // step over the space
    return result;
}

}  // namespace nq
