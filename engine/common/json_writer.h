// A small streaming JSON writer for the tools' --json output (no DOM, no dependencies).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace nq {

class JsonWriter {
public:
    explicit JsonWriter(bool pretty = true) : pretty_(pretty) {}

    JsonWriter& begin_object();
    JsonWriter& end_object();
    JsonWriter& begin_array();
    JsonWriter& end_array();
    JsonWriter& key(std::string_view k);  // must be followed by a value or begin_*

    JsonWriter& value(std::string_view s);
    JsonWriter& value(const char* s) { return value(std::string_view(s)); }
    JsonWriter& value(const std::string& s) { return value(std::string_view(s)); }
    JsonWriter& value(bool b);
    JsonWriter& value(int64_t n);
    JsonWriter& value(int n) { return value(static_cast<int64_t>(n)); }
    JsonWriter& value(uint32_t n) { return value(static_cast<int64_t>(n)); }
    JsonWriter& value(uint64_t n);
    JsonWriter& value(double d);  // NaN/inf become null
    JsonWriter& null();

    template <class T>
    JsonWriter& field(std::string_view k, const T& v) { key(k); return value(v); }

    const std::string& str() const { return out_; }

private:
    void before_value();
    void newline();

    std::string out_;
    std::vector<bool> has_items_;  // per open container: has it any element yet?
    bool after_key_ = false;
    bool pretty_;
};

std::string json_escape(std::string_view s);

}  // namespace nq
