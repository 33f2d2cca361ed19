// Reading a save file into plain data. The header is words separated by whitespace (Quake reads
// it with sscanf); the globals and edicts are brace blocks of "key" "value" tokens as COM_Parse
// splits them (comments skipped, so QuakeSpasm-Spiked's commented extensions are ignored).
// Everything is checked here, so applying the data later cannot meet a malformed number.
#include <algorithm>
#include <charconv>
#include <cmath>

#include "server/savegame.h"

namespace nq::server {

namespace {

bool is_space(unsigned char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

struct Token {
    std::string text;
    size_t offset = 0;
    bool quoted = false;
    bool end = false;  // no token left
    bool is(char c) const { return !quoted && text.size() == 1 && text[0] == c; }
};

class SaveReader {
  public:
    SaveReader(std::string_view text, const std::string& file) : text_(text), file_(file) {}

    LoadedGame read() {
        if (size_t nul = text_.find('\0'); nul != std::string_view::npos) {
            fail(nul, "NUL byte in the text of a save");
        }
        LoadedGame game;
        game.file_name = file_;
        read_version();
        game.comment = std::string(word("the comment").text);
        for (float& parm : game.spawn_parms) parm = number("a spawn parm");
        game.skill = skill();
        game.map_offset = skip_space();
        game.map = map_name();
        game.time = clock();
        for (std::string& style : game.lightstyles) style = std::string(word("a light style").text);
        read_blocks(game);
        return game;
    }

  private:
    struct Word {
        std::string_view text;
        size_t offset = 0;
    };

    [[noreturn]] void fail(size_t offset, std::string message) const {
        throw FormatError(Error{file_, offset, std::move(message)});
    }

    // ---- the header: words
    size_t skip_space() {
        while (pos_ < text_.size() && is_space(uint8_t(text_[pos_]))) ++pos_;
        return pos_;
    }

    Word word(const char* what) {
        skip_space();
        if (pos_ == text_.size()) fail(pos_, std::string("truncated: expected ") + what);
        const size_t start = pos_;
        while (pos_ < text_.size() && !is_space(uint8_t(text_[pos_]))) ++pos_;
        if (pos_ - start > kSaveMaxToken) {
            fail(start,
                 std::string(what) + " is longer than " + std::to_string(kSaveMaxToken) + " bytes");
        }
        return {text_.substr(start, pos_ - start), start};
    }

    template <class T>
    T parse_number(const Word& w, const char* what) const {
        std::string_view s = w.text;
        if (s.size() > 1 && s[0] == '+') s.remove_prefix(1);
        T value{};
        const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
        if (ec == std::errc::result_out_of_range) {
            fail(w.offset, std::string(what) + " '" + std::string(w.text) + "' is out of range");
        }
        if (ec != std::errc() || end != s.data() + s.size()) {
            fail(w.offset, std::string(what) + " '" + std::string(w.text) + "' is not a number");
        }
        return value;
    }

    float number(const char* what) { return parse_number<float>(word(what), what); }

    void read_version() {
        const Word w = word("the version");
        const int version = parse_number<int>(w, "the version");
        if (version != kSaveVersion) {
            fail(w.offset, "version " + std::to_string(version) + ": only version " +
                               std::to_string(kSaveVersion) + " (id Quake, QuakeSpasm) is read");
        }
    }

    // Quake 1.06 wrote the skill as a float: it is rounded the same way and kept to 0..3.
    int skill() {
        const Word w = word("the skill");
        const float value = parse_number<float>(w, "the skill");
        if (!std::isfinite(value)) fail(w.offset, "the skill is not a finite number");
        return int(std::clamp(value + 0.1f, 0.0f, 3.0f));
    }

    std::string map_name() {
        const Word w = word("the map name");
        const bool bad = w.text.size() >= 64 || w.text.find("..") != std::string_view::npos ||
                         w.text.find_first_of("/\\:") == 0;
        if (bad) fail(w.offset, "'" + std::string(w.text) + "' is not a map name");
        return std::string(w.text);
    }

    double clock() {
        const Word w = word("the server time");
        const double value = parse_number<double>(w, "the server time");
        if (!(value >= 0 && value < 1e9)) {
            fail(w.offset, "the server time " + std::string(w.text) + " is out of range");
        }
        return value;
    }

    // ---- the blocks: COM_Parse's tokens
    void skip_space_and_comments() {
        while (pos_ < text_.size()) {
            if (uint8_t(text_[pos_]) <= ' ') {
                ++pos_;
            } else if (text_.substr(pos_, 2) == "//") {
                const size_t eol = text_.find('\n', pos_);
                pos_ = eol == std::string_view::npos ? text_.size() : eol;
            } else if (text_.substr(pos_, 2) == "/*") {
                const size_t close = text_.find("*/", pos_ + 2);
                pos_ = close == std::string_view::npos ? text_.size() : close + 2;
            } else {
                return;
            }
        }
    }

    static bool is_single(char c) {
        return c == '{' || c == '}' || c == '(' || c == ')' || c == '\'' || c == ':';
    }

    Token token() {
        skip_space_and_comments();
        Token t;
        t.offset = pos_;
        if (pos_ == text_.size()) {
            t.end = true;
            return t;
        }
        if (text_[pos_] == '"') {
            const size_t close = text_.find('"', pos_ + 1);
            if (close == std::string_view::npos)
                fail(pos_, "truncated: a string without a closing quote");
            t.text = std::string(text_.substr(pos_ + 1, close - pos_ - 1));
            t.quoted = true;
            pos_ = close + 1;
        } else if (is_single(text_[pos_])) {
            t.text = std::string(1, text_[pos_++]);
        } else {
            const size_t start = pos_;
            while (pos_ < text_.size() && uint8_t(text_[pos_]) > ' ' &&
                   (pos_ == start || !is_single(text_[pos_]))) {
                ++pos_;
            }
            t.text = std::string(text_.substr(start, pos_ - start));
        }
        if (t.text.size() > kSaveMaxToken) {
            fail(t.offset, "a token longer than " + std::to_string(kSaveMaxToken) + " bytes");
        }
        return t;
    }

    SavedBlock block(const Token& open) {
        SavedBlock b;
        b.offset = open.offset;
        for (;;) {
            Token key = token();
            if (key.end)
                fail(key.offset, "truncated: the block at offset " + std::to_string(open.offset) +
                                     " has no closing brace");
            if (key.is('}')) return b;
            if (key.is('{')) fail(key.offset, "'{' inside a block (a closing brace is missing)");
            Token value = token();
            if (value.end) fail(value.offset, "truncated: '" + key.text + "' has no value");
            if (value.is('}') || value.is('{')) {
                fail(value.offset, "'" + key.text + "' has no value before the brace");
            }
            b.pairs.push_back({std::move(key.text), std::move(value.text), key.offset});
        }
    }

    void read_blocks(LoadedGame& game) {
        bool have_globals = false;
        for (Token open = token(); !open.end; open = token()) {
            if (!open.is('{')) fail(open.offset, "expected '{', found '" + open.text + "'");
            if (!have_globals) {
                game.globals = block(open);
                have_globals = true;
            } else {
                game.edicts.push_back(block(open));
            }
        }
        if (!have_globals) fail(pos_, "truncated: no globals block");
        if (game.edicts.size() < 2) {
            fail(pos_, "truncated: " + std::to_string(game.edicts.size()) +
                           " edicts; a save holds at least the world and the player");
        }
    }

    std::string_view text_;
    const std::string& file_;
    size_t pos_ = 0;
};

}  // namespace

Result<LoadedGame> read_savegame(std::string_view text, const std::string& file_name) {
    return capture_errors(file_name, [&] { return SaveReader(text, file_name).read(); });
}

}  // namespace nq::server
