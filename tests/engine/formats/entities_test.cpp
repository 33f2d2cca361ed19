// Entity lumps: the text grammar (quotes, bare words, comments, order, duplicates), errors with
// offsets, vector values, and the entity lumps of the LibreQuake maps counted independently.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <sstream>

#include "formats/bsp.h"
#include "formats/entities.h"
#include "support/test_data.h"

namespace nq {
namespace {

EntityList parse_ok(std::string_view text, uint64_t base = 0) {
    auto list = parse_entities(text, "test.bsp", base);
    if (!list) throw std::runtime_error(list.error().to_string());
    return std::move(list).value();
}

Error parse_error(std::string_view text, uint64_t base = 0) {
    auto list = parse_entities(text, "test.bsp", base);
    if (list) throw std::runtime_error("bad entity text parsed without error");
    return list.error();
}

TEST(Entities, KeysKeepTheirOrderAndDuplicates) {
    const std::string text =
        "{\n\"classname\" \"worldspawn\"\n\"wad\" \"gfx.wad\"\n}\n"
        "{ \"classname\" \"light\" \"light\" \"200\" \"light\" \"300\" }";
    const EntityList list = parse_ok(text, 500);
    ASSERT_EQ(list.entities.size(), 2u);
    const Entity& light = list.entities[1];
    ASSERT_EQ(light.pairs.size(), 3u);
    EXPECT_EQ(light.pairs[0], (std::pair<std::string, std::string>{"classname", "light"}));
    EXPECT_EQ(light.pairs[1].second, "200");
    EXPECT_EQ(light.pairs[2].second, "300");
    EXPECT_EQ(find_value(light, "light"), "300");  // the last one wins, as in the game
    EXPECT_FALSE(find_value(light, "origin").has_value());
    EXPECT_EQ(classname(list.entities[0]), "worldspawn");
    EXPECT_EQ(list.entities[0].offset, 500u);
    EXPECT_EQ(list.entities[1].offset, 500u + text.find('{', 1));
    EXPECT_TRUE(list.warnings.empty());
}

TEST(Entities, CommentsBareWordsAndOddSpacing) {
    const EntityList list = parse_ok(
        "// a comment before anything { \"not\" \"parsed\" }\n"
        "{\r\n\t\"classname\"\"info_player_start\" // trailing comment\n"
        "origin \"1 2 3\"\n\"message\" \"a // inside quotes is text\"\n"
        "\"empty\" \"\"\n\"brace\" \"{\"}");
    ASSERT_EQ(list.entities.size(), 1u);
    const Entity& e = list.entities[0];
    EXPECT_EQ(classname(e), "info_player_start");
    EXPECT_EQ(find_value(e, "origin"), "1 2 3");
    EXPECT_EQ(find_value(e, "message"), "a // inside quotes is text");
    EXPECT_EQ(find_value(e, "empty"), "");
    EXPECT_EQ(find_value(e, "brace"), "{");  // quoted braces are values
}

TEST(Entities, TextEndsAtTheFirstNul) {
    const std::string text("{ \"classname\" \"worldspawn\" }\0{ garbage", 38);
    EXPECT_EQ(parse_ok(text).entities.size(), 1u);
    EXPECT_TRUE(parse_ok("").entities.empty());
    EXPECT_TRUE(parse_ok("  \n// only a comment").entities.empty());
}

TEST(Entities, MissingFinalBraceNamesTheEntityOffset) {
    const Error e =
        parse_error("{ \"classname\" \"worldspawn\" }\n{ \"classname\" \"light\"", 1000);
    EXPECT_EQ(e.file, "test.bsp");
    EXPECT_NE(e.message.find("entity starting at offset 1029 has no closing brace"),
              std::string::npos)
        << e.message;
    EXPECT_EQ(e.offset, 1000u + 50);  // where the text ran out
}

TEST(Entities, MalformedTextIsAnErrorAtItsOffset) {
    Error e = parse_error("{ \"classname\" \"light }", 10);
    EXPECT_EQ(e.offset, 10u + 14);
    EXPECT_NE(e.message.find("unterminated quoted string"), std::string::npos);

    e = parse_error("{ \"classname\" }");
    EXPECT_EQ(e.offset, 2u);
    EXPECT_NE(e.message.find("key \"classname\" has no value"), std::string::npos);

    e = parse_error("\"classname\" \"light\"");
    EXPECT_EQ(e.offset, 0u);
    EXPECT_NE(e.message.find("expected '{'"), std::string::npos);

    e = parse_error("{ \"a\" \"b\" { \"c\" \"d\" } }");
    EXPECT_EQ(e.offset, 10u);
    EXPECT_NE(e.message.find("'{' inside the entity"), std::string::npos);

    e = parse_error("{ \"a\" \"b\" } }");
    EXPECT_EQ(e.offset, 12u);
}

TEST(Entities, EntitiesWithoutClassnameAreWarnedAbout) {
    const EntityList list = parse_ok("{ \"origin\" \"0 0 0\" }");
    ASSERT_EQ(list.warnings.size(), 1u);
    EXPECT_NE(list.warnings[0].find("entity 0 (offset 0) has no classname"), std::string::npos);
}

TEST(Entities, Vec3Values) {
    EXPECT_EQ(parse_vec3("1 -2.5 3e2"), (std::array<float, 3>{1, -2.5f, 300}));
    EXPECT_EQ(parse_vec3("  +4\t5  6 "), (std::array<float, 3>{4, 5, 6}));
    EXPECT_FALSE(parse_vec3("1 2"));
    EXPECT_FALSE(parse_vec3("1 2 3 4"));
    EXPECT_FALSE(parse_vec3("1 two 3"));
    EXPECT_FALSE(parse_vec3("1 2 nan"));
    EXPECT_FALSE(parse_vec3("1 2 1e99"));
    EXPECT_FALSE(parse_vec3("1 2 +-3"));
    EXPECT_FALSE(parse_vec3(""));
    const EntityList list = parse_ok("{ \"classname\" \"light\" \"origin\" \"8 16 -24\" }");
    EXPECT_EQ(find_vec3(list.entities[0], "origin"), (std::array<float, 3>{8, 16, -24}));
    EXPECT_FALSE(find_vec3(list.entities[0], "angles"));
}

// ---- LibreQuake maps ----------------------------------------------------------------------

std::string read_text(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

TEST(EntitiesReal, EveryMapsEntitiesMatchAnIndependentCount) {
    for (const auto& path : test::lq1_files("maps", ".bsp")) {
        SCOPED_TRACE(path);
        const std::string raw = read_text(path);
        auto bsp = parse_bsp({reinterpret_cast<const uint8_t*>(raw.data()), raw.size()}, path);
        ASSERT_TRUE(bsp) << bsp.error().to_string();
        auto list = parse_entities(bsp->entities, path, bsp->entities_offset);
        ASSERT_TRUE(list) << list.error().to_string();
        // Compilers write each entity's braces on lines of their own, and one pair per line.
        size_t opening = 0, pairs = 0;
        std::istringstream lines(bsp->entities);
        for (std::string line; std::getline(lines, line);) {
            if (line == "{") ++opening;
            if (!line.empty() && line[0] == '"') ++pairs;
        }
        EXPECT_EQ(list->entities.size(), opening);
        size_t parsed_pairs = 0;
        for (const Entity& e : list->entities) parsed_pairs += e.pairs.size();
        EXPECT_EQ(parsed_pairs, pairs);
        EXPECT_EQ(classname(list->entities.at(0)), "worldspawn");
        EXPECT_EQ(list->entities[0].offset, bsp->entities_offset + bsp->entities.find('{'));
        EXPECT_TRUE(list->warnings.empty());
    }
}

TEST(EntitiesReal, StartMapHasLightsWithOrigins) {
    const std::string path = test::lq1_dir() + "/maps/start.bsp";
    const std::string raw = read_text(path);
    auto bsp = parse_bsp({reinterpret_cast<const uint8_t*>(raw.data()), raw.size()}, path);
    ASSERT_TRUE(bsp);
    auto list = parse_entities(bsp->entities, path, bsp->entities_offset);
    ASSERT_TRUE(list);
    size_t lights = 0;
    for (const Entity& e : list->entities) {
        if (!classname(e).starts_with("light")) continue;
        ++lights;
        EXPECT_TRUE(find_vec3(e, "origin").has_value());
    }
    EXPECT_GT(lights, 0u);
}

}  // namespace
}  // namespace nq
