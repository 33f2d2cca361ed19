#include "illustrative/material_file.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string_view>

namespace nq::npr::illustrative {
namespace {

struct Token {
    std::string text;
    bool quoted = false;
};

// Per line: the tokens, or a soft problem that makes the line be skipped.
struct LineTokens {
    std::vector<Token> tokens;
    std::string problem;
};

class Parser {
  public:
    explicit Parser(MaterialParseResult& out) : out_(out) {}
    void line(int number, std::string_view text);
    void finish(int last_line);

  private:
    void warn(const std::string& message) { out_.warnings.push_back({line_, message}); }
    void statement(const std::vector<Token>& tokens);
    void assign(const std::string& key, const std::string& value);
    std::optional<float> number(const std::string& key, const std::string& value, float lo,
                                float hi);
    std::optional<bool> flag(const std::string& key, const std::string& value);
    std::optional<std::array<float, 3>> triple(const std::string& key, const std::string& value);

    MaterialParseResult& out_;
    int line_ = 0;
    int depth_ = 0;
    bool seen_statement_ = false;
    std::vector<std::string> keys_seen_;
};

std::string lower(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

// Splits one line into tokens: "quoted strings", { and }, and bare words; `//` outside quotes
// ends the line.
LineTokens tokenize(std::string_view line) {
    LineTokens out;
    size_t i = 0;
    while (i < line.size()) {
        const char c = line[i];
        if (is_space(c)) {
            ++i;
        } else if (c == '/' && i + 1 < line.size() && line[i + 1] == '/') {
            break;
        } else if (c == '{' || c == '}') {
            out.tokens.push_back({std::string(1, c), false});
            ++i;
        } else if (c == '"') {
            const size_t end = line.find('"', i + 1);
            if (end == std::string_view::npos) {
                out.problem = "unterminated quoted string";
                return out;
            }
            out.tokens.push_back({std::string(line.substr(i + 1, end - i - 1)), true});
            i = end + 1;
        } else {
            size_t end = i;
            while (end < line.size() && !is_space(line[end]) && line[end] != '"' &&
                   line[end] != '{' && line[end] != '}' &&
                   !(line[end] == '/' && end + 1 < line.size() && line[end + 1] == '/')) {
                ++end;
            }
            out.tokens.push_back({std::string(line.substr(i, end - i)), false});
            i = end;
        }
    }
    return out;
}

// Strict float: the whole text, finite.
std::optional<float> parse_float(std::string_view text) {
    while (!text.empty() && is_space(text.front())) text.remove_prefix(1);
    while (!text.empty() && is_space(text.back())) text.remove_suffix(1);
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    float value = 0.0f;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size() || text.empty()) return std::nullopt;
    if (!std::isfinite(value)) return std::nullopt;
    return value;
}

void Parser::line(int number, std::string_view text) {
    line_ = number;
    LineTokens t = tokenize(text);
    if (!t.problem.empty()) {
        warn(t.problem + ", line ignored");
        return;
    }
    // Braces only group; what matters is the key/value pairs between them.
    std::vector<Token> words;
    for (const Token& token : t.tokens) {
        if (!token.quoted && token.text == "{") {
            ++depth_;
        } else if (!token.quoted && token.text == "}") {
            if (depth_ == 0) {
                warn("unmatched }");
            } else {
                --depth_;
            }
        } else {
            words.push_back(token);
        }
    }
    if (!words.empty()) statement(words);
}

void Parser::finish(int last_line) {
    line_ = last_line;
    if (depth_ > 0) warn("missing } at end of file");
}

void Parser::statement(const std::vector<Token>& words) {
    const bool first = !seen_statement_;
    seen_statement_ = true;
    // A lone word before any key is the shader name ("VertexLitGeneric"), whose value is
    // the braced block.
    if (words.size() == 1 && first && words[0].text.rfind('$', 0) != 0) return;
    const std::string key = lower(words[0].text);
    if (words.size() == 1) {
        warn("key " + words[0].text + " has no value");
        return;
    }
    std::string value = words[1].text;
    size_t used = 2;
    // An unquoted [a b c] arrives as several words: join them back.
    if (!words[1].quoted && !value.empty() && value.front() == '[') {
        while (value.back() != ']' && used < words.size() && !words[used].quoted) {
            value += " " + words[used].text;
            ++used;
        }
    }
    if (used < words.size()) warn("extra text after the value of " + words[0].text + " ignored");
    if (std::find(keys_seen_.begin(), keys_seen_.end(), key) != keys_seen_.end()) {
        warn("key " + words[0].text + " repeated, the last value counts");
    } else {
        keys_seen_.push_back(key);
    }
    assign(key, value);
}

std::optional<float> Parser::number(const std::string& key, const std::string& value, float lo,
                                    float hi) {
    const std::optional<float> v = parse_float(value);
    if (!v) {
        warn("bad number \"" + value + "\" for " + key + ", ignored");
        return std::nullopt;
    }
    const float clamped = std::clamp(*v, lo, hi);
    if (clamped != *v) {
        warn(key + " " + value + " out of range [" + std::to_string(lo) + ", " +
             std::to_string(hi) + "], clamped to " + std::to_string(clamped));
    }
    return clamped;
}

std::optional<bool> Parser::flag(const std::string& key, const std::string& value) {
    const std::optional<float> v = parse_float(value);
    if (!v || (*v != 0.0f && *v != 1.0f)) {
        warn("bad value \"" + value + "\" for " + key + " (0 or 1), ignored");
        return std::nullopt;
    }
    return *v != 0.0f;
}

std::optional<std::array<float, 3>> Parser::triple(const std::string& key,
                                                   const std::string& value) {
    std::string_view inner = value;
    while (!inner.empty() && is_space(inner.front())) inner.remove_prefix(1);
    while (!inner.empty() && is_space(inner.back())) inner.remove_suffix(1);
    if (inner.size() < 2 || inner.front() != '[' || inner.back() != ']') {
        warn("bad value \"" + value + "\" for " + key + " (expected \"[a b c]\"), ignored");
        return std::nullopt;
    }
    inner = inner.substr(1, inner.size() - 2);
    std::array<float, 3> out{};
    size_t count = 0;
    size_t i = 0;
    while (i < inner.size()) {
        if (is_space(inner[i])) {
            ++i;
            continue;
        }
        size_t end = i;
        while (end < inner.size() && !is_space(inner[end])) ++end;
        const std::optional<float> v = parse_float(inner.substr(i, end - i));
        if (!v || count == 3) {
            warn("bad value \"" + value + "\" for " + key + " (expected three numbers), ignored");
            return std::nullopt;
        }
        out[count++] = *v;
        i = end;
    }
    if (count != 3) {
        warn("bad value \"" + value + "\" for " + key + " (expected three numbers), ignored");
        return std::nullopt;
    }
    for (float& v : out) {
        const float clamped = std::clamp(v, 0.0f, 10.0f);
        if (clamped != v) warn(key + " component out of range [0, 10], clamped");
        v = clamped;
    }
    return out;
}

void Parser::assign(const std::string& key, const std::string& value) {
    MaterialOverrides& m = out_.material;
    auto keep = [](auto& field, auto v) {
        if (v) field = v;
    };
    if (key == "$phongexponent") {
        keep(m.phong_exponent, number(key, value, 1.0f, 1000.0f));
    } else if (key == "$phongboost") {
        keep(m.phong_boost, number(key, value, 0.0f, 100.0f));
    } else if (key == "$phongfresnelranges") {
        keep(m.phong_fresnel_ranges, triple(key, value));
    } else if (key == "$rimlight") {
        keep(m.rim_light, flag(key, value));
    } else if (key == "$rimlightexponent") {
        keep(m.rim_light_exponent, number(key, value, 0.1f, 100.0f));
    } else if (key == "$rimlightboost") {
        keep(m.rim_light_boost, number(key, value, 0.0f, 100.0f));
    } else if (key == "$rimmask") {
        keep(m.rim_mask, flag(key, value));
    } else if (key == "$lightwarptexture") {
        if (value.empty()) {
            warn("empty value for " + key + ", ignored");
        } else {
            m.light_warp_texture = value;
        }
    } else if (key == "$selfillum") {
        keep(m.self_illum, flag(key, value));
    } else if (key == "$ambientscale") {
        keep(m.ambient_scale, number(key, value, 0.0f, 10.0f));
    } else {
        warn("unknown key " + key + ", ignored");
    }
}

// Text is anything but control characters other than tab, CR, LF, VT, FF; bytes >= 0x80 are
// allowed (UTF-8 in comments). Returns the offset of the first binary byte, or npos.
size_t first_binary_byte(std::span<const uint8_t> bytes) {
    for (size_t i = 0; i < bytes.size(); ++i) {
        const uint8_t b = bytes[i];
        if ((b < 0x20 && b != '\t' && b != '\r' && b != '\n' && b != '\v' && b != '\f') ||
            b == 0x7f) {
            return i;
        }
    }
    return std::string_view::npos;
}

int line_of_offset(std::span<const uint8_t> bytes, size_t offset) {
    return 1 + int(std::count(bytes.begin(), bytes.begin() + long(offset), uint8_t('\n')));
}

MaterialParseResult fail(const std::string& file, int line, const std::string& problem) {
    MaterialParseResult out;
    out.error_line = line;
    out.error =
        line > 0 ? file + ":" + std::to_string(line) + ": " + problem : file + ": " + problem;
    return out;
}

}  // namespace

MaterialParseResult parse_material_file(std::span<const uint8_t> bytes, const std::string& file) {
    if (bytes.size() > kMaxMaterialFileSize) {
        return fail(file, 0,
                    "file is " + std::to_string(bytes.size()) + " bytes, over the " +
                        std::to_string(kMaxMaterialFileSize) + " byte limit for a material file");
    }
    if (const size_t bad = first_binary_byte(bytes); bad != std::string_view::npos) {
        char hex[8];
        std::snprintf(hex, sizeof hex, "0x%02x", unsigned(bytes[bad]));
        return fail(file, line_of_offset(bytes, bad),
                    "binary data (byte " + std::string(hex) + " at offset " + std::to_string(bad) +
                        "), not a text material file");
    }
    MaterialParseResult out;
    Parser parser(out);
    const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    int number = 0;
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        ++number;
        if (end - start > kMaxMaterialLineLength) {
            return fail(file, number,
                        "line is " + std::to_string(end - start) + " characters, over the " +
                            std::to_string(kMaxMaterialLineLength) + " character limit");
        }
        parser.line(number, text.substr(start, end - start));
        start = end + 1;
    }
    parser.finish(number);
    return out;
}

std::string format_material_warning(const std::string& file, const MaterialWarning& warning) {
    return file + ":" + std::to_string(warning.line) + ": " + warning.message;
}

}  // namespace nq::npr::illustrative
