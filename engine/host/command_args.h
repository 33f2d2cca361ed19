// One parsed command: its tokens (argv[0] is the command name) and the raw text they came
// from, so that commands like `alias` and `bind` can take "the rest of the line" verbatim,
// quotes included.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace nq {

class CommandArgs {
  public:
    CommandArgs() = default;
    // `text`: the command's source text (no separator, comment or trailing spaces);
    // `starts[i]`: where token i begins in it (at its opening quote when quoted).
    CommandArgs(std::vector<std::string> tokens, std::string text, std::vector<size_t> starts);
    // For code that builds a command from tokens: the raw text is the tokens, quoted where
    // needed, joined by spaces.
    static CommandArgs from_tokens(std::vector<std::string> tokens);

    bool empty() const { return tokens_.empty(); }
    size_t argc() const { return tokens_.size(); }
    // Token i, or "" past the end (Quake's Cmd_Argv convention).
    const std::string& argv(size_t i) const;
    const std::string& name() const { return argv(0); }
    const std::vector<std::string>& tokens() const { return tokens_; }
    // The raw text from token `first` to the end of the command ("" past the end).
    std::string_view rest(size_t first) const;
    // Everything after the command name, raw: rest(1).
    std::string_view args() const { return rest(1); }
    // Token `index` when it is the last one, else the raw rest from it: "the value" for
    // commands whose last argument may be typed with or without quotes.
    std::string value_from(size_t index) const;

  private:
    std::vector<std::string> tokens_;
    std::string text_;
    std::vector<size_t> starts_;
};

}  // namespace nq
