// The illustrative plugin's cvar table: every entry's default gives exactly the defaults written
// in IllustrativeSettings (two places that must agree), values reach their fields and are
// clamped, only changed cvars are re-read, the Options menu names only real cvars, and
// docs/console.md documents every cvar with its default.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "support/cvar_table_test_support.h"
#include "illustrative/illustrative_cvars.h"

namespace nq::npr::illustrative {
namespace {

using test::console_doc;
using test::fake_engine;
using test::FakeCvars;
using test::g_fake;

class IllustrativeCvarsTest : public ::testing::Test {
  protected:
    void SetUp() override { g_fake = &fake_; }
    void TearDown() override { g_fake = nullptr; }
    FakeCvars fake_;
};

TEST_F(IllustrativeCvarsTest, TableDefaultsAreTheSettingsDefaults) {
    const nqr_engine engine = fake_engine();
    IllustrativeCvars cvars;
    cvars.register_all(engine);
    // Start from values unlike any default, so a binding that writes nothing is caught.
    IllustrativeSettings s;
    s.half_lambert_alpha = s.half_lambert_beta = s.half_lambert_gamma = -1;
    s.warp_ramp = "?";
    s.ambient_scale = s.light_scale = -1;
    s.max_lights = -1;
    s.specular = s.rim = s.dedicated_rim = s.skin_masks = s.smooth_normals = false;
    s.material.phong_exponent = s.material.phong_boost = s.material.rim_exponent = -1;
    s.material.rim_boost = -1;
    s.material.fresnel_ranges[0] = s.material.fresnel_ranges[1] = s.material.fresnel_ranges[2] = -1;
    s.crease_angle_degrees = s.team_saturation = s.height_gradient_floor = -1;
    s.height_gradient = true;
    s.abstract_world = false;
    s.abstract_radius = -1;
    s.world_saturation = s.world_contrast = -1;
    s.show = ShowTerm::rim;
    cvars.update(s);
    const IllustrativeSettings d;
    EXPECT_FLOAT_EQ(s.half_lambert_alpha, d.half_lambert_alpha);
    EXPECT_FLOAT_EQ(s.half_lambert_beta, d.half_lambert_beta);
    EXPECT_FLOAT_EQ(s.half_lambert_gamma, d.half_lambert_gamma);
    EXPECT_EQ(s.warp_ramp, d.warp_ramp);
    EXPECT_FLOAT_EQ(s.ambient_scale, d.ambient_scale);
    EXPECT_FLOAT_EQ(s.light_scale, d.light_scale);
    EXPECT_EQ(s.max_lights, d.max_lights);
    EXPECT_EQ(s.specular, d.specular);
    EXPECT_EQ(s.rim, d.rim);
    EXPECT_EQ(s.dedicated_rim, d.dedicated_rim);
    EXPECT_FLOAT_EQ(s.material.phong_exponent, d.material.phong_exponent);
    EXPECT_FLOAT_EQ(s.material.phong_boost, d.material.phong_boost);
    for (int i = 0; i < 3; ++i) {
        EXPECT_FLOAT_EQ(s.material.fresnel_ranges[i], d.material.fresnel_ranges[i]) << i;
    }
    EXPECT_FLOAT_EQ(s.material.rim_exponent, d.material.rim_exponent);
    EXPECT_FLOAT_EQ(s.material.rim_boost, d.material.rim_boost);
    EXPECT_EQ(s.skin_masks, d.skin_masks);
    EXPECT_EQ(s.smooth_normals, d.smooth_normals);
    EXPECT_FLOAT_EQ(s.crease_angle_degrees, d.crease_angle_degrees);
    EXPECT_FLOAT_EQ(s.team_saturation, d.team_saturation);
    EXPECT_EQ(s.height_gradient, d.height_gradient);
    EXPECT_FLOAT_EQ(s.height_gradient_floor, d.height_gradient_floor);
    EXPECT_EQ(s.abstract_world, d.abstract_world);
    EXPECT_EQ(s.abstract_radius, d.abstract_radius);
    EXPECT_FLOAT_EQ(s.world_saturation, d.world_saturation);
    EXPECT_FLOAT_EQ(s.world_contrast, d.world_contrast);
    EXPECT_EQ(s.show, d.show);
}

TEST_F(IllustrativeCvarsTest, NamesAreUniqueAndDescribedAndTheMenuNamesOnlyThem) {
    std::set<std::string> names;
    for (const CvarBinding& b : illustrative_cvar_bindings()) {
        EXPECT_TRUE(names.insert(b.name).second) << b.name;
        EXPECT_EQ(std::string(b.name).rfind("ill_", 0), 0u) << b.name;
        EXPECT_GT(std::string(b.description).size(), 10u) << b.name;
    }
    for (const nqr_menu_setting& m : illustrative_menu_settings()) {
        EXPECT_EQ(m.size, sizeof(nqr_menu_setting));
        EXPECT_TRUE(names.count(m.cvar)) << m.cvar;
        EXPECT_LE(std::string(m.label).size(), 20u) << m.label;
    }
}

TEST_F(IllustrativeCvarsTest, ChangedValuesReachTheirFieldsClampedAndOnlyChangedOnesAreReRead) {
    const nqr_engine engine = fake_engine();
    IllustrativeCvars cvars;
    cvars.register_all(engine);
    IllustrativeSettings s;
    cvars.update(s);
    fake_.set("ill_ramp", "gfx/ramps/warm.png");
    fake_.set("ill_fresnel_ranges", "[0.5 2 4]");
    fake_.set("ill_max_lights", "9");  // clamped to 4
    fake_.set("ill_show", "3");
    fake_.set("ill_phong_exponent", "0");  // clamped to 1
    s.material.rim_boost = 99;             // its cvar did not change: kept
    cvars.update(s);
    EXPECT_EQ(s.warp_ramp, "gfx/ramps/warm.png");
    EXPECT_FLOAT_EQ(s.material.fresnel_ranges[0], 0.5f);
    EXPECT_FLOAT_EQ(s.material.fresnel_ranges[1], 2.0f);
    EXPECT_FLOAT_EQ(s.material.fresnel_ranges[2], 4.0f);
    EXPECT_EQ(s.max_lights, 4);
    EXPECT_EQ(s.show, ShowTerm::warped_diffuse);
    EXPECT_FLOAT_EQ(s.material.phong_exponent, 1.0f);
    EXPECT_FLOAT_EQ(s.material.rim_boost, 99.0f);
    fake_.set("ill_fresnel_ranges", "0.7");  // one value: all three
    cvars.update(s);
    EXPECT_FLOAT_EQ(s.material.fresnel_ranges[2], 0.7f);
}

TEST_F(IllustrativeCvarsTest, ConsoleDocListsEveryCvarWithItsDefault) {
    const std::string doc = console_doc();
    ASSERT_FALSE(doc.empty()) << "docs/console.md not found above " << nq::test::bin_dir();
    for (const CvarBinding& b : illustrative_cvar_bindings()) {
        const std::string cell = "| `" + std::string(b.name) + "` | `" + b.default_value + "` |";
        EXPECT_NE(doc.find(cell), std::string::npos) << "docs/console.md lacks the row " << cell;
    }
}

}  // namespace
}  // namespace nq::npr::illustrative
