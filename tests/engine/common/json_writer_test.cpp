#include <gtest/gtest.h>

#include <cmath>

#include "common/json_writer.h"

namespace nq {
namespace {

TEST(JsonWriter, CompactNestedDocument) {
    JsonWriter w(false);
    w.begin_object();
    w.field("name", "ogre.mdl").field("frames", 3).field("ok", true);
    w.key("bbox").begin_array().value(1.5).value(-2.0).end_array();
    w.key("empty").begin_object().end_object();
    w.end_object();
    EXPECT_EQ(w.str(), R"({"name":"ogre.mdl","frames":3,"ok":true,"bbox":[1.5,-2],"empty":{}})");
}

TEST(JsonWriter, EscapesControlAndHighBytes) {
    EXPECT_EQ(json_escape("a\"b\\c\n"), "a\\\"b\\\\c\\n");
    // Quake's coloured text uses bytes >= 128: they must not produce invalid UTF-8 in JSON.
    EXPECT_EQ(json_escape(std::string("\x80\x01", 2)), "\\u0080\\u0001");
}

TEST(JsonWriter, NonFiniteNumbersBecomeNull) {
    JsonWriter w(false);
    w.begin_array().value(std::nan("")).value(INFINITY).end_array();
    EXPECT_EQ(w.str(), "[null,null]");
}

}  // namespace
}  // namespace nq
