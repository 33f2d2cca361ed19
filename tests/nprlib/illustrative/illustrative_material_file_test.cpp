// Material files (progs/*.mdl.mat): VMT-like keys, soft problems as warnings with line numbers,
// hard problems (binary data, long lines, big files) as an error the caller falls back from.
#include <gtest/gtest.h>

#include <string>

#include "illustrative/material_file.h"

namespace nq::npr::illustrative {
namespace {

MaterialParseResult parse(const std::string& text) {
    return parse_material_file(
        std::span<const uint8_t>(reinterpret_cast<const uint8_t*>(text.data()), text.size()),
        "progs/ogre.mdl.mat");
}

bool has_warning(const MaterialParseResult& r, int line, const std::string& part) {
    for (const MaterialWarning& w : r.warnings) {
        if (w.line == line && w.message.find(part) != std::string::npos) return true;
    }
    return false;
}

TEST(IllustrativeMaterialFile, VmtStyleFileSetsEveryKey) {
    const MaterialParseResult r = parse(
        "\"VertexLitGeneric\"\n"
        "{\n"
        "    // the ogre: leathery, a strong rim\n"
        "    \"$phongexponent\" \"25\"\n"
        "    $phongboost 2.5\n"
        "    \"$phongfresnelranges\" \"[0.05 0.5 1]\"\n"
        "    $rimlight 1\n"
        "    $rimlightexponent 4   // tight rim\n"
        "    $rimlightboost \"2\"\n"
        "    $rimmask 0\n"
        "    $lightwarptexture \"gfx/warp ramp.png\"\n"
        "    $selfillum 1\n"
        "    $AmbientScale 0.5\n"
        "}\n");
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_TRUE(r.warnings.empty()) << format_material_warning("f", r.warnings.front());
    const MaterialOverrides& m = r.material;
    EXPECT_EQ(m.phong_exponent, 25.0f);
    EXPECT_EQ(m.phong_boost, 2.5f);
    ASSERT_TRUE(m.phong_fresnel_ranges);
    EXPECT_FLOAT_EQ((*m.phong_fresnel_ranges)[0], 0.05f);
    EXPECT_FLOAT_EQ((*m.phong_fresnel_ranges)[1], 0.5f);
    EXPECT_FLOAT_EQ((*m.phong_fresnel_ranges)[2], 1.0f);
    EXPECT_EQ(m.rim_light, true);
    EXPECT_EQ(m.rim_light_exponent, 4.0f);
    EXPECT_EQ(m.rim_light_boost, 2.0f);
    EXPECT_EQ(m.rim_mask, false);
    EXPECT_EQ(m.light_warp_texture, "gfx/warp ramp.png");
    EXPECT_EQ(m.self_illum, true);
    EXPECT_EQ(m.ambient_scale, 0.5f);
}

TEST(IllustrativeMaterialFile, BareKeysWithoutBracesAndUnsetFieldsStayEmpty) {
    const MaterialParseResult r = parse("$phongboost 3\r\n$lightwarptexture cel\r\n");
    ASSERT_TRUE(r.ok());
    EXPECT_TRUE(r.warnings.empty());
    EXPECT_EQ(r.material.phong_boost, 3.0f);
    EXPECT_EQ(r.material.light_warp_texture, "cel");
    EXPECT_FALSE(r.material.phong_exponent);
    EXPECT_FALSE(r.material.rim_light);
    EXPECT_FALSE(r.material.phong_fresnel_ranges);
}

TEST(IllustrativeMaterialFile, ShaderNameAndBraceOnOneLine) {
    const MaterialParseResult r = parse("VertexLitGeneric {\n$rimlight 1 }\n");
    ASSERT_TRUE(r.ok());
    EXPECT_TRUE(r.warnings.empty());
    EXPECT_EQ(r.material.rim_light, true);
}

TEST(IllustrativeMaterialFile, UnquotedFresnelRangesAreJoined) {
    const MaterialParseResult r = parse("$phongfresnelranges [0.2 0.6 0.9]\n");
    ASSERT_TRUE(r.material.phong_fresnel_ranges);
    EXPECT_FLOAT_EQ((*r.material.phong_fresnel_ranges)[1], 0.6f);
    EXPECT_TRUE(r.warnings.empty());
}

TEST(IllustrativeMaterialFile, SoftProblemsWarnWithTheirLine) {
    const MaterialParseResult r = parse(
        "$phongexponent 25\n"              // 1: fine
        "$shiny 1\n"                       // 2: unknown key
        "$phongboost lots\n"               // 3: bad number
        "$rimlightboost 1000\n"            // 4: clamped to 100
        "$rimlight 2\n"                    // 5: not 0/1
        "$phongfresnelranges \"[1 2]\"\n"  // 6: two numbers
        "$ambientscale\n"                  // 7: no value
        "$phongexponent 0\n"               // 8: repeated, and clamped to 1
        "$selfillum \"1\n"                 // 9: unterminated quote
        "$phongboost nan\n"                // 10: not finite
        "}\n");                            // 11: unmatched
    ASSERT_TRUE(r.ok());
    EXPECT_TRUE(has_warning(r, 2, "unknown key $shiny"));
    EXPECT_TRUE(has_warning(r, 3, "bad number"));
    EXPECT_TRUE(has_warning(r, 4, "clamped"));
    EXPECT_TRUE(has_warning(r, 5, "0 or 1"));
    EXPECT_TRUE(has_warning(r, 6, "three numbers"));
    EXPECT_TRUE(has_warning(r, 7, "no value"));
    EXPECT_TRUE(has_warning(r, 8, "repeated"));
    EXPECT_TRUE(has_warning(r, 8, "clamped"));
    EXPECT_TRUE(has_warning(r, 9, "unterminated"));
    EXPECT_TRUE(has_warning(r, 10, "bad number"));
    EXPECT_TRUE(has_warning(r, 11, "unmatched"));
    EXPECT_EQ(r.material.rim_light_boost, 100.0f);
    EXPECT_EQ(r.material.phong_exponent, 1.0f);  // the last value, clamped
    EXPECT_FALSE(r.material.phong_boost);
    EXPECT_FALSE(r.material.rim_light);
    EXPECT_FALSE(r.material.self_illum);
    EXPECT_EQ(format_material_warning("progs/ogre.mdl.mat", r.warnings.front())
                  .rfind("progs/ogre.mdl.mat:2: ", 0),
              0u);
}

TEST(IllustrativeMaterialFile, MissingCloseBraceWarnsAtTheEnd) {
    const MaterialParseResult r = parse("\"VertexLitGeneric\" {\n$rimlight 1\n");
    ASSERT_TRUE(r.ok());
    EXPECT_TRUE(has_warning(r, 2, "missing }"));
    EXPECT_EQ(r.material.rim_light, true);
}

TEST(IllustrativeMaterialFile, BinaryDataIsAnErrorWithItsLine) {
    std::string text = "$rimlight 1\n$phongboost 2\n$x ";
    text.push_back('\0');
    text += "\n";
    const MaterialParseResult r = parse(text);
    EXPECT_FALSE(r.ok());
    EXPECT_EQ(r.error_line, 3);
    EXPECT_NE(r.error.find("progs/ogre.mdl.mat:3:"), std::string::npos) << r.error;
    EXPECT_NE(r.error.find("binary"), std::string::npos);
    EXPECT_FALSE(r.material.rim_light);  // nothing half-applied
}

TEST(IllustrativeMaterialFile, LongLineAndHugeFileAreErrors) {
    std::string text = "$rimlight 1\n// " + std::string(kMaxMaterialLineLength, 'x') + "\n";
    MaterialParseResult r = parse(text);
    EXPECT_FALSE(r.ok());
    EXPECT_EQ(r.error_line, 2);
    EXPECT_NE(r.error.find("limit"), std::string::npos);

    std::string big;
    while (big.size() <= kMaxMaterialFileSize) big += "// padding line\n";
    r = parse(big);
    EXPECT_FALSE(r.ok());
    EXPECT_NE(r.error.find("progs/ogre.mdl.mat"), std::string::npos);
    EXPECT_NE(r.error.find("byte limit"), std::string::npos);
}

TEST(IllustrativeMaterialFile, EmptyFileSetsNothing) {
    const MaterialParseResult r = parse("");
    EXPECT_TRUE(r.ok());
    EXPECT_TRUE(r.warnings.empty());
    EXPECT_FALSE(r.material.phong_boost);
}

}  // namespace
}  // namespace nq::npr::illustrative
