// Entity lump parsing: a small tokenizer (quoted strings, bare words, braces, // comments) and
// the block grammar on top of it.
#include "formats/entities.h"

#include <charconv>
#include <cmath>

namespace nq {

namespace {

struct Token {
    std::string text;
    size_t pos = 0;       // offset of the token's first byte in the text
    bool quoted = false;  // a quoted "{" is a value, not a brace
    bool is(char c) const { return !quoted && text.size() == 1 && text[0] == c; }
};

class Tokenizer {
  public:
    Tokenizer(std::string_view text, const std::string& name, uint64_t base)
        : text_(text), name_(name), base_(base) {}

    // The next token, or nothing at the end of the text.
    std::optional<Token> next() {
        skip_blanks_and_comments();
        if (pos_ >= text_.size()) return std::nullopt;
        Token t;
        t.pos = pos_;
        const char c = text_[pos_];
        if (c == '"') return quoted(t);
        if (c == '{' || c == '}') {
            t.text = std::string(1, c);
            ++pos_;
            return t;
        }
        while (pos_ < text_.size() && !is_blank(text_[pos_]) && text_[pos_] != '"' &&
               text_[pos_] != '{' && text_[pos_] != '}' && !at_comment()) {
            t.text += text_[pos_++];
        }
        return t;
    }

    size_t pos() const { return pos_; }
    [[noreturn]] void fail(size_t pos, const std::string& message) const {
        throw FormatError(Error{name_, base_ + pos, message});
    }

  private:
    static bool is_blank(char c) { return static_cast<unsigned char>(c) <= ' '; }
    bool at_comment() const {
        return pos_ + 1 < text_.size() && text_[pos_] == '/' && text_[pos_ + 1] == '/';
    }

    void skip_blanks_and_comments() {
        while (pos_ < text_.size()) {
            if (is_blank(text_[pos_])) {
                ++pos_;
            } else if (at_comment()) {
                while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
            } else {
                return;
            }
        }
    }

    Token quoted(Token t) {
        const size_t close = text_.find('"', pos_ + 1);
        if (close == std::string_view::npos) fail(t.pos, "unterminated quoted string");
        t.text = std::string(text_.substr(pos_ + 1, close - pos_ - 1));
        t.quoted = true;
        pos_ = close + 1;
        return t;
    }

    std::string_view text_;
    const std::string& name_;
    uint64_t base_;
    size_t pos_ = 0;
};

// After the '{' at `open`: key/value pairs up to the matching '}'.
Entity parse_entity(Tokenizer& tok, size_t open, uint64_t base) {
    Entity e;
    e.offset = base + open;
    auto unclosed = [&] {
        tok.fail(tok.pos(), "entity starting at offset " + std::to_string(base + open) +
                                " has no closing brace before the end of the text");
    };
    for (;;) {
        auto key = tok.next();
        if (!key) unclosed();
        if (key->is('}')) return e;
        if (key->is('{')) {
            tok.fail(key->pos, "'{' inside the entity starting at offset " +
                                   std::to_string(base + open) + " (missing '}'?)");
        }
        auto value = tok.next();
        if (!value) unclosed();
        if (value->is('{') || value->is('}')) {
            tok.fail(key->pos, "key \"" + key->text + "\" has no value");
        }
        e.pairs.emplace_back(std::move(key->text), std::move(value->text));
    }
}

}  // namespace

Result<EntityList> parse_entities(std::string_view text, const std::string& name,
                                  uint64_t base_offset) {
    return capture_errors(name, [&]() -> EntityList {
        text = text.substr(0, text.find('\0'));
        Tokenizer tok(text, name, base_offset);
        EntityList list;
        while (auto t = tok.next()) {
            if (!t->is('{')) {
                tok.fail(t->pos, "expected '{' to start an entity, found \"" + t->text + "\"");
            }
            list.entities.push_back(parse_entity(tok, t->pos, base_offset));
            if (classname(list.entities.back()).empty()) {
                list.warnings.push_back("entity " + std::to_string(list.entities.size() - 1) +
                                        " (offset " + std::to_string(base_offset + t->pos) +
                                        ") has no classname");
            }
        }
        return list;
    });
}

Result<EntityList> parse_entities(std::span<const uint8_t> text, const std::string& name,
                                  uint64_t base_offset) {
    return parse_entities(std::string_view(reinterpret_cast<const char*>(text.data()), text.size()),
                          name, base_offset);
}

std::optional<std::string_view> find_value(const Entity& entity, std::string_view key) {
    for (auto it = entity.pairs.rbegin(); it != entity.pairs.rend(); ++it) {
        if (it->first == key) return std::string_view(it->second);
    }
    return std::nullopt;
}

std::string_view classname(const Entity& entity) {
    return find_value(entity, "classname").value_or(std::string_view());
}

std::vector<const Entity*> find_entities(const EntityList& list, std::string_view name) {
    std::vector<const Entity*> out;
    for (const Entity& e : list.entities) {
        if (classname(e) == name) out.push_back(&e);
    }
    return out;
}

std::optional<std::array<float, 3>> parse_vec3(std::string_view text) {
    std::array<float, 3> v{};
    const char* p = text.data();
    const char* end = text.data() + text.size();
    auto skip_blanks = [&] {
        while (p < end && static_cast<unsigned char>(*p) <= ' ') ++p;
    };
    for (float& c : v) {
        skip_blanks();
        if (p < end && *p == '+' && (end - p < 2 || p[1] != '-')) ++p;  // from_chars refuses '+'
        auto [next, ec] = std::from_chars(p, end, c);
        if (ec != std::errc() || !std::isfinite(c)) return std::nullopt;
        p = next;
    }
    skip_blanks();
    if (p != end) return std::nullopt;
    return v;
}

std::optional<std::array<float, 3>> find_vec3(const Entity& entity, std::string_view key) {
    auto value = find_value(entity, key);
    return value ? parse_vec3(*value) : std::nullopt;
}

}  // namespace nq
