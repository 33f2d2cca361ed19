// The engine-wide volumetric obscurance: the vo_* cvars (defaults as documented in
// docs/console.md and as the pass's settings say, values reaching the settings, an unknown
// vo_mode refused with a warning), and the engine drawing it under a style that does not ask
// for the G-buffer: the showroom with vo_show 1 is white where nothing is near (sky, open
// floor) and darker where the models stand on the floor, and the picture with it on is the
// picture without it times that.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "app/obscurance_cvars.h"
#include "support/cvar_table_test_support.h"
#include "support/build_paths.h"
#include "support/engine_run.h"
#include "video/png_io.h"

namespace nq {
namespace {

using npr::obscurance::ObscuranceMode;
using npr::obscurance::ObscuranceSettings;

const char* const kCvars[] = {
    "vo_enable", "vo_mode", "vo_radius", "vo_radius2", "vo_dual_min", "vo_thickness", "vo_strength",
    "vo_normal", "vo_blur", "vo_half",   "vo_show",    "vo_compute",  "vo_shift"};

TEST(ObscuranceCvars, DefaultsAreTheSettingsDefaultsAndTheDocumentedOnes) {
    CvarRegistry registry;
    ObscuranceCvars cvars;
    cvars.register_cvars(registry, {});
    const ObscuranceSettings& s = cvars.settings();
    const ObscuranceSettings d;
    EXPECT_EQ(s.enabled, d.enabled);
    EXPECT_EQ(s.mode, d.mode);
    EXPECT_EQ(s.radius, d.radius);
    EXPECT_EQ(s.radius2, d.radius2);
    EXPECT_EQ(s.dual, d.dual);
    EXPECT_EQ(s.thickness, d.thickness);
    EXPECT_EQ(s.strength, d.strength);
    EXPECT_EQ(s.normal_clamp, d.normal_clamp);
    EXPECT_EQ(s.shift, d.shift);
    EXPECT_EQ(s.blur, d.blur);
    EXPECT_EQ(s.half_resolution, d.half_resolution);
    EXPECT_EQ(s.show, d.show);
    EXPECT_EQ(s.compute, d.compute);
    const std::string doc = npr::test::console_doc();
    ASSERT_FALSE(doc.empty());
    for (const char* name : kCvars) {
        const Cvar* cvar = registry.find(name);
        ASSERT_NE(cvar, nullptr) << name;
        const std::string row = "| `" + std::string(name) + "` | `" + cvar->default_value() + "` |";
        EXPECT_NE(doc.find(row), std::string::npos) << "docs/console.md lacks " << row;
    }
}

TEST(ObscuranceCvars, ValuesReachTheSettingsAndABadModeWarns) {
    CvarRegistry registry;
    ObscuranceCvars cvars;
    std::vector<std::string> warnings;
    cvars.register_cvars(registry, [&](const std::string& w) { warnings.push_back(w); });
    registry.set("vo_enable", "1");
    registry.set("vo_mode", "points33");
    registry.set("vo_radius", "0");  // clamped to 1
    registry.set("vo_radius2", "64");
    registry.set("vo_dual_min", "1");
    registry.set("vo_half", "1");
    registry.set("vo_compute", "0");
    registry.set("vo_shift", "0");
    ObscuranceSettings s = cvars.settings();
    EXPECT_TRUE(s.enabled);
    EXPECT_EQ(s.mode, ObscuranceMode::points33);
    EXPECT_EQ(s.radius, 1.0f);
    EXPECT_EQ(s.radius2, 64.0f);
    EXPECT_EQ(s.dual, npr::obscurance::DualRadius::minimum);
    EXPECT_TRUE(s.half_resolution);
    EXPECT_EQ(s.compute, npr::obscurance::ComputeUse::off);
    EXPECT_FALSE(s.shift);
    EXPECT_TRUE(warnings.empty());
    registry.set("vo_shift", "1");
    EXPECT_TRUE(cvars.settings().shift);
    registry.set("vo_compute", "1");
    EXPECT_EQ(cvars.settings().compute, npr::obscurance::ComputeUse::on);
    registry.set("vo_compute", "2");
    EXPECT_EQ(cvars.settings().compute, npr::obscurance::ComputeUse::fastest);
    registry.set("vo_mode", "area7");
    s = cvars.settings();
    EXPECT_EQ(s.mode, ObscuranceMode::lines5);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("area7"), std::string::npos) << warnings[0];
    s = cvars.settings();  // nothing changed: not read (nor warned) again
    EXPECT_EQ(warnings.size(), 1u);
}

struct Shot {
    std::vector<int> grey;  // red channel per pixel
    int width = 0, height = 0;
    int at(int x, int y) const { return grey[size_t(y) * size_t(width) + size_t(x)]; }
};

Shot showroom_shot(const std::vector<std::string>& settings) {
    test::TempDir tmp("nq_vo");
    const std::string shot = tmp.file("shot.png");
    std::vector<std::string> args = {
        "-userdir", tmp.path(),     "-basedir", tmp.subdir("nodata"), "-width", "160", "-height",
        "120",      "+scr_drawhud", "0",        "+showroom_time",     "5"};
    args.insert(args.end(), settings.begin(), settings.end());
    for (const char* tail : {"+wait", "+wait", "+screenshot"}) args.push_back(tail);
    args.push_back(shot);
    args.push_back("+quit");
    const auto run = test::run_nprquake(args, tmp.path());
    EXPECT_EQ(run.exit_code, 0) << run.describe();
    EXPECT_EQ(run.out.find("obscurance off"), std::string::npos) << run.out;
    auto image = read_png(shot);
    Shot out;
    if (!image.ok()) {
        ADD_FAILURE() << image.error().to_string();
        return out;
    }
    out.width = image->width;
    out.height = image->height;
    for (size_t i = 0; i < image->rgb.size(); i += 3) out.grey.push_back(image->rgb[i]);
    return out;
}

TEST(EngineObscurance, TheShowroomIsOpenOnSkyAndFloorAndDarkerWhereModelsStand) {
    const Shot shown = showroom_shot({"+vo_enable", "1", "+vo_show", "1"});
    ASSERT_EQ(shown.width, 160);
    // Below the console's lines at the top: nothing drawn, untouched.
    for (int x = 0; x < shown.width; x += 4) EXPECT_EQ(shown.at(x, 12), 255) << x;
    int white = 0, dark = 0;
    for (int v : shown.grey) {
        white += v >= 245;
        dark += v < 200;
    }
    EXPECT_GT(white, int(shown.grey.size()) / 2);  // sky and the open floor
    EXPECT_GT(dark, 20);                           // contact and creases exist
    // The plain picture through the same scene framebuffer (the window may be multisampled).
    const Shot off = showroom_shot({"+vo_enable", "1", "+vo_strength", "0"});
    const Shot on = showroom_shot({"+vo_enable", "1"});
    ASSERT_EQ(off.grey.size(), on.grey.size());
    // Same frame three times (showroom_time): the picture is the plain one times what vo_show
    // draws, pixel by pixel.
    int changed = 0, wrong = 0;
    for (size_t i = 0; i < off.grey.size(); ++i) {
        const int expected = int(std::lround(off.grey[i] * shown.grey[i] / 255.0));
        if (i < 10 * size_t(off.width)) continue;  // the console's lines, drawn afterwards
        wrong += std::abs(on.grey[i] - expected) > 3;
        changed += on.grey[i] < off.grey[i] - 8;
    }
    EXPECT_EQ(wrong, 0);
    EXPECT_GT(changed, 10);
}

// One run through every style and swaps between them, in the modes with state of their own
// (area1's moments, the reference): each picture shows the obscurance with open sky and floor
// and dark contact, and the pass never fails.
TEST(EngineObscurance, EveryStyleShowsItThroughSwaps) {
    for (const char* mode : {"lines5", "area1"}) {
        std::vector<std::string> settings = {"+vo_enable", "1", "+vo_show", "1", "+vo_mode", mode};
        for (const char* style : {"classic", "technical", "illustrative", "classic"}) {
            settings.insert(settings.end(), {"+r_plugin", style, "+wait", "+wait"});
            const Shot shown = showroom_shot(settings);
            ASSERT_EQ(shown.width, 160) << mode << " " << style;
            int white = 0, dark = 0;
            for (int v : shown.grey) {
                white += v >= 245;
                dark += v < 200;
            }
            EXPECT_GT(white, int(shown.grey.size()) / 2) << mode << " " << style;
            EXPECT_GT(dark, 20) << mode << " " << style;
        }
    }
}

}  // namespace
}  // namespace nq
