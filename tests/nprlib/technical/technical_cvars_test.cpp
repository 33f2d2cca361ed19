// The technical plugin's cvar table: every entry's default gives exactly the defaults written in
// TechnicalSettings (two places that must agree), values reach their fields, colours parse, only
// changed cvars are re-read, and docs/console.md documents every cvar with its default.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "support/cvar_table_test_support.h"
#include "technical/technical_cvars.h"

namespace nq::npr::technical {
namespace {

using test::console_doc;
using test::fake_engine;
using test::FakeCvars;
using test::g_fake;

class TechnicalCvarsTest : public ::testing::Test {
  protected:
    void SetUp() override { g_fake = &fake_; }
    void TearDown() override { g_fake = nullptr; }
    FakeCvars fake_;
};

void expect_vec3(const glm::vec3& a, const glm::vec3& b, const char* what) {
    EXPECT_FLOAT_EQ(a.x, b.x) << what;
    EXPECT_FLOAT_EQ(a.y, b.y) << what;
    EXPECT_FLOAT_EQ(a.z, b.z) << what;
}

TEST_F(TechnicalCvarsTest, TableDefaultsAreTheSettingsDefaults) {
    const nqr_engine engine = fake_engine();
    TechnicalCvars cvars;
    cvars.register_all(engine);
    TechnicalSettings from_cvars;
    // Start from values unlike any default, so a binding that writes nothing is caught.
    from_cvars.edges.crease_angle_degrees = -1;
    from_cvars.shading.splashback_p = -1;
    from_cvars.shadows.alpha = -1;
    cvars.update(from_cvars);
    const TechnicalSettings d;
    EXPECT_EQ(from_cvars.edges.silhouettes, d.edges.silhouettes);
    EXPECT_EQ(from_cvars.edges.creases, d.edges.creases);
    EXPECT_FLOAT_EQ(from_cvars.edges.crease_angle_degrees, d.edges.crease_angle_degrees);
    EXPECT_FLOAT_EQ(from_cvars.edges.silhouette_width, d.edges.silhouette_width);
    EXPECT_FLOAT_EQ(from_cvars.edges.ridge_width, d.edges.ridge_width);
    EXPECT_FLOAT_EQ(from_cvars.edges.valley_width, d.edges.valley_width);
    expect_vec3(from_cvars.edges.silhouette_color, d.edges.silhouette_color, "silhouette colour");
    expect_vec3(from_cvars.edges.ridge_color, d.edges.ridge_color, "ridge colour");
    expect_vec3(from_cvars.edges.valley_color, d.edges.valley_color, "valley colour");
    EXPECT_EQ(from_cvars.edges.color_mode, d.edges.color_mode);
    EXPECT_FLOAT_EQ(from_cvars.edges.white_w, d.edges.white_w);
    EXPECT_EQ(from_cvars.edges.distance_fade, d.edges.distance_fade);
    EXPECT_FLOAT_EQ(from_cvars.edges.fade_distance, d.edges.fade_distance);
    EXPECT_FLOAT_EQ(from_cvars.edges.depth_offset, d.edges.depth_offset);
    EXPECT_EQ(from_cvars.edges.backface_lines, d.edges.backface_lines);
    EXPECT_FLOAT_EQ(from_cvars.edges.backface_width, d.edges.backface_width);
    EXPECT_EQ(from_cvars.edges.world_edges, d.edges.world_edges);
    EXPECT_EQ(from_cvars.shading.mode, d.shading.mode);
    EXPECT_FLOAT_EQ(from_cvars.shading.blue, d.shading.blue);
    EXPECT_FLOAT_EQ(from_cvars.shading.yellow, d.shading.yellow);
    EXPECT_FLOAT_EQ(from_cvars.shading.alpha, d.shading.alpha);
    EXPECT_FLOAT_EQ(from_cvars.shading.beta, d.shading.beta);
    EXPECT_EQ(from_cvars.shading.splashback, d.shading.splashback);
    EXPECT_FLOAT_EQ(from_cvars.shading.splashback_alpha, d.shading.splashback_alpha);
    EXPECT_FLOAT_EQ(from_cvars.shading.splashback_p, d.shading.splashback_p);
    EXPECT_FLOAT_EQ(from_cvars.shading.texture_blend, d.shading.texture_blend);
    EXPECT_FLOAT_EQ(from_cvars.shading.metal_bands, d.shading.metal_bands);
    EXPECT_EQ(from_cvars.shadows.enabled, d.shadows.enabled);
    EXPECT_EQ(from_cvars.shadows.penumbra, d.shadows.penumbra);
    expect_vec3(from_cvars.shadows.color, d.shadows.color, "shadow colour");
    EXPECT_FLOAT_EQ(from_cvars.shadows.alpha, d.shadows.alpha);
    EXPECT_FLOAT_EQ(from_cvars.shadows.penumbra_alpha, d.shadows.penumbra_alpha);
    EXPECT_FLOAT_EQ(from_cvars.shadows.umbra_scale, d.shadows.umbra_scale);
    EXPECT_FLOAT_EQ(from_cvars.shadows.penumbra_offset, d.shadows.penumbra_offset);
    EXPECT_FLOAT_EQ(from_cvars.shadows.max_drop, d.shadows.max_drop);
    EXPECT_FLOAT_EQ(from_cvars.shadows.max_distance, d.shadows.max_distance);
}

TEST_F(TechnicalCvarsTest, NamesAreUniqueAndDescribed) {
    std::set<std::string> names;
    for (const CvarBinding& b : technical_cvar_bindings()) {
        EXPECT_TRUE(names.insert(b.name).second) << b.name;
        EXPECT_EQ(std::string(b.name).rfind("tech_", 0), 0u) << b.name;
        EXPECT_GT(std::string(b.description).size(), 10u) << b.name;
    }
    EXPECT_GE(names.size(), 30u);
}

TEST_F(TechnicalCvarsTest, ChangedValuesReachTheirFieldsAndOnlyChangedOnesAreReRead) {
    const nqr_engine engine = fake_engine();
    TechnicalCvars cvars;
    cvars.register_all(engine);
    TechnicalSettings s;
    cvars.update(s);
    fake_.set("tech_white", "0.9");
    fake_.set("tech_shading", "2");
    fake_.set("tech_ridge_color", "1 0.5 0");
    fake_.set("tech_valley_color", "0.25");  // one component: grey
    fake_.set("tech_shadow_alpha", "7");     // clamped to 1
    fake_.set("tech_edge_colors", "9");      // clamped to the last mode
    // A field changed behind the table's back stays: its cvar did not change.
    s.edges.silhouette_width = 99;
    cvars.update(s);
    EXPECT_FLOAT_EQ(s.edges.white_w, 0.9f);
    EXPECT_EQ(s.shading.mode, ShadingMode::metal);
    expect_vec3(s.edges.ridge_color, {1.0f, 0.5f, 0.0f}, "ridge");
    expect_vec3(s.edges.valley_color, glm::vec3(0.25f), "valley");
    EXPECT_FLOAT_EQ(s.shadows.alpha, 1.0f);
    EXPECT_EQ(s.edges.color_mode, EdgeColorMode::white_all);
    EXPECT_FLOAT_EQ(s.edges.silhouette_width, 99.0f);
}

TEST_F(TechnicalCvarsTest, ConsoleDocListsEveryCvarWithItsDefault) {
    const std::string doc = console_doc();
    ASSERT_FALSE(doc.empty()) << "docs/console.md not found above " << nq::test::bin_dir();
    for (const CvarBinding& b : technical_cvar_bindings()) {
        const std::string cell = "| `" + std::string(b.name) + "` | `" + b.default_value + "` |";
        EXPECT_NE(doc.find(cell), std::string::npos) << "docs/console.md lacks the row " << cell;
    }
}

}  // namespace
}  // namespace nq::npr::technical
