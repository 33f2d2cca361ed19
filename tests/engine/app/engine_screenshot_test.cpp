// What the engine binary puts on screen: a textured, lit world during a demo; alias models
// exactly where their entities project; the built-in showroom when there is no game data.
#include <gtest/gtest.h>

#include <sstream>

#include "support/engine_demo_replay.h"
#include "support/engine_image_checks.h"
#include "support/engine_output_checks.h"
#include "engine_projection.h"
#include "support/engine_runs.h"

namespace nq {
namespace {

using namespace test;
using engine_runs::kHeight;
using engine_runs::kWidth;

// ------------------------------------------------------------------ a textured, lit world

double colour_distance(const RegionStats& a, const RegionStats& b) {
    double d = 0;
    for (int i = 0; i < 3; ++i) d += std::pow(a.mean_rgb[i] - b.mean_rgb[i], 2);
    return std::sqrt(d);
}

TEST(EngineScreenshot, DemoFramesShowATexturedLitWorld) {
    const SharedRun& run = engine_runs::demo_classic();
    expect_clean_exit(run.result);
    Vfs vfs = mount_lq1();
    DemoReplay replay(vfs, "demo.dem");  // for the camera's pitch and roll at each frame
    int level_frames = 0;
    for (uint64_t frame : engine_runs::kScreenshotFrames) {
        SCOPED_TRACE("demo frame " + std::to_string(frame));
        RgbImage image;
        ASSERT_NO_FATAL_FAILURE(
            load_screenshot(engine_runs::shot(run.dir, "classic", frame), image));
        ASSERT_EQ(image.width, kWidth);
        ASSERT_EQ(image.height, kHeight);
        RegionStats all = region_stats(image, whole(image));
        // Textures and lightmaps give thousands of colours; a clear colour or a flat fill
        // gives one or a handful.
        EXPECT_GT(all.distinct_colours, 1000u);
        EXPECT_LT(all.most_common_fraction, 0.10);
        EXPECT_GT(all.luminance_stddev, 12.0);
        EXPECT_GT(all.mean_luminance, 20.0);   // lit, not black
        EXPECT_LT(all.mean_luminance, 200.0);  // not washed out

        // Looking about level, the top quarter shows what is above the eye (sky or ceiling)
        // and the bottom quarter the floor: different surfaces, different colours.
        ASSERT_TRUE(replay.play_to(frame));
        const Vec3& angles = replay.view().angles;
        if (std::abs(angles[0]) > 30.0f || std::abs(angles[2]) > 10.0f) continue;
        ++level_frames;
        RegionStats top = region_stats(image, {0, 0, kWidth, kHeight / 4});
        RegionStats bottom = region_stats(image, {0, kHeight * 3 / 4, kWidth, kHeight});
        EXPECT_GT(colour_distance(top, bottom), 20.0) << "top and bottom quarters look alike";
    }
    EXPECT_GE(level_frames, 3) << "too few frames look about level to compare up and down";
}

// ------------------------------------------------------------------ models where they project
//
// How this check works, and why it catches misplaced models:
// The alias-only test plugin (tests/plugins/alias_only_plugin.c) makes the engine draw its
// alias models with its default drawer and nothing else, on black. The test replays the same
// demo in-process (DemoReplay), takes each alias entity's exact pose vertices from its MDL,
// places them with the entity's origin and angles and projects them with Quake's camera
// conventions (engine_projection.h: none of the engine's matrix code). So for every entity it
// knows the screen rectangle its model must cover. Then:
//   1. every lit pixel of the alias-only screenshot lies inside some entity's rectangle: a model
//      drawn anywhere else (shifted, mirrored, turned the wrong way, under a wrong field of
//      view) leaves pixels outside;
//   2. for the largest upright entity in plain view (a BSP trace from the eye reaches it) whose
//      rectangle and a ring around it are mostly clear of other models' rectangles, the
//      rectangle is well filled and the ring is empty: the model is there, not next to it;
//   3. the classic renderer's screenshot of that frame shows the same model pixels there.
// The candidate is chosen programmatically among the frames the runs screenshot. The view
// model (the weapon) is never a candidate; its rectangle is extended to the bottom edge, where
// its parts behind the near plane are clipped.

struct Region {
    ScreenBox box;
    uint32_t entity = 0;
    std::string model;
    bool view_model = false;
};

struct FrameLayout {
    std::vector<Region> regions;  // every alias entity in front of the camera
    bool complete = true;         // false: some entity straddles the near plane
    std::vector<Region> candidates;
};

// World positions of the vertices of both poses an entity blends (a blend of the two lies
// between them, and so does its projection).
std::vector<V3> entity_vertices(const Mdl& mdl, const VisibleEntity& e) {
    auto poses = numbered_poses(mdl);
    std::vector<V3> out;
    for (uint32_t index : {e.pose.pose0, e.pose.pose1}) {
        if (index >= poses.size()) continue;
        auto v = posed_vertices_world(mdl, *poses[index], {e.origin[0], e.origin[1], e.origin[2]},
                                      {e.angles[0], e.angles[1], e.angles[2]}, e.scale);
        out.insert(out.end(), v.begin(), v.end());
    }
    return out;
}

V3 centre_of(const std::vector<V3>& points) {
    V3 lo{1e9f, 1e9f, 1e9f}, hi{-1e9f, -1e9f, -1e9f};
    for (const V3& p : points) {
        for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], p[i]), hi[i] = std::max(hi[i], p[i]);
    }
    return {(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
}

FrameLayout layout_of_frame(DemoReplay& replay) {
    FrameLayout layout;
    const ViewResult& view = replay.view();
    const V3 eye{view.origin[0], view.origin[1], view.origin[2]};
    QuakeProjector camera(eye, {view.angles[0], view.angles[1], view.angles[2]}, 90.0f, kWidth,
                          kHeight);
    for (const VisibleEntity& e : replay.visible_entities().entities()) {
        const Mdl* mdl = replay.alias_mdl(e.model);
        if (!mdl) continue;  // brush models and sprites are not drawn by the alias-only plugin
        std::vector<V3> vertices = entity_vertices(*mdl, e);
        if (vertices.empty() || camera.all_outside(vertices)) continue;  // off screen
        Region region;
        region.entity = e.number;
        region.model = replay.client().model_names()[e.model];
        region.view_model = (e.flags & kVisibleViewModel) != 0;
        size_t behind = 0;
        for (const V3& p : vertices) {
            if (auto s = camera.project(p)) {
                region.box.add(*s);
            } else {
                ++behind;
            }
        }
        if (region.view_model) {
            // Parts of the weapon may reach behind the near plane; the clipped rest runs off
            // the bottom of the screen.
            region.box.y1 = kHeight;
            region.box = region.box.grown(4);
        } else if (behind > 0) {
            layout.complete = false;  // its clipped shape could reach anywhere
        }
        layout.regions.push_back(region);

        bool upright = std::abs(e.angles[0]) < 0.01f && std::abs(e.angles[2]) < 0.01f;
        if (!region.view_model && behind == 0 && upright && region.box.inside(kWidth, kHeight, 4) &&
            region.box.width() * region.box.height() >= 300 &&
            replay.line_of_sight(eye, centre_of(vertices))) {
            layout.candidates.push_back(region);
        }
    }
    return layout;
}

// The window around a candidate in which it is checked: its own box, and a ring around it
// that must stay empty.
ScreenBox window_around(const ScreenBox& box) {
    return box.grown(std::max(8.0f, 0.5f * std::max(box.width(), box.height())));
}

// Where a pixel lies with respect to a candidate: in its own box (grown by 2 pixels for
// rasterisation), in the ring around it, or where another model may be drawn (any other
// region, grown by 2) or outside the window.
enum class Place { own, ring, elsewhere };

Place place_of(int x, int y, const Region& candidate, const FrameLayout& layout) {
    float px = x + 0.5f, py = y + 0.5f;
    for (const Region& other : layout.regions) {
        if (other.entity != candidate.entity && other.box.grown(2).contains(px, py)) {
            return Place::elsewhere;
        }
    }
    if (candidate.box.grown(2).contains(px, py)) return Place::own;
    return window_around(candidate.box).contains(px, py) ? Place::ring : Place::elsewhere;
}

struct PixelCounts {
    size_t own = 0, ring = 0;          // pixels of each place
    size_t lit_own = 0, lit_ring = 0;  // of those, lit in the alias-only shot
    size_t matching_classic = 0;       // lit_own pixels the classic shot agrees on
};

PixelCounts count_pixels(const Region& candidate, const FrameLayout& layout,
                         const RgbImage* alias = nullptr, const RgbImage* classic = nullptr) {
    PixelCounts c;
    ScreenBox window = window_around(candidate.box);
    for (int y = std::max(0, int(window.y0)); y < std::min(kHeight, int(window.y1) + 1); ++y) {
        for (int x = std::max(0, int(window.x0)); x < std::min(kWidth, int(window.x1) + 1); ++x) {
            Place place = place_of(x, y, candidate, layout);
            if (place == Place::elsewhere) continue;
            bool lit = alias && !is_black(pixel(*alias, x, y));
            if (place == Place::own) {
                ++c.own;
                c.lit_own += lit;
                if (lit && classic && near_colour(pixel(*alias, x, y), pixel(*classic, x, y), 8)) {
                    ++c.matching_classic;
                }
            } else {
                ++c.ring;
                c.lit_ring += lit;
            }
        }
    }
    return c;
}

// Enough of the candidate's box and of the ring around it is free of other models.
bool checkable(const Region& candidate, const FrameLayout& layout) {
    PixelCounts c = count_pixels(candidate, layout);
    float area = candidate.box.width() * candidate.box.height();
    return c.own >= 0.5f * area && c.own >= 300 && c.ring >= 0.5f * area;
}

// Lit pixels of the alias-only screenshot outside every region (grown by 2 pixels).
size_t stray_pixels(const RgbImage& alias, const FrameLayout& layout) {
    size_t stray = 0;
    for (int y = 0; y < alias.height; ++y) {
        for (int x = 0; x < alias.width; ++x) {
            if (is_black(pixel(alias, x, y))) continue;
            bool covered = false;
            for (const Region& r : layout.regions) {
                covered = covered || r.box.grown(2).contains(x + 0.5f, y + 0.5f);
            }
            if (!covered) ++stray;
        }
    }
    return stray;
}

struct Candidate {
    uint64_t frame = 0;
    Region region;
    FrameLayout layout;
    size_t own = 0;  // pixels only it may cover
};

std::string describe(const Region& r) {
    std::ostringstream s;
    s << "entity " << r.entity << " (" << r.model << ") at [" << r.box.x0 << ", " << r.box.y0
      << "] - [" << r.box.x1 << ", " << r.box.y1 << "]";
    return s.str();
}

TEST(EngineScreenshot, AliasModelsAppearWhereTheirEntitiesProject) {
    const SharedRun& alias_run = engine_runs::demo_alias_only();
    const SharedRun& classic_run = engine_runs::demo_classic();
    expect_clean_exit(alias_run.result);
    ASSERT_NE(alias_run.result.out.find("renderer: alias_only"), std::string::npos)
        << "the alias-only test plugin did not load (is nqr_test_alias_only.so built into "
        << engine_runs::alias_only_plugin_dir() << "?)\n"
        << alias_run.result.out;

    Vfs vfs = mount_lq1();
    DemoReplay replay(vfs, "demo.dem");
    std::optional<Candidate> best;
    size_t frames_checked = 0;
    for (uint64_t frame : engine_runs::kScreenshotFrames) {
        SCOPED_TRACE("demo frame " + std::to_string(frame));
        ASSERT_TRUE(replay.play_to(frame));
        FrameLayout layout = layout_of_frame(replay);
        RgbImage alias;
        ASSERT_NO_FATAL_FAILURE(
            load_screenshot(engine_runs::shot(alias_run.dir, "alias", frame), alias));
        if (layout.complete) {
            ++frames_checked;
            EXPECT_LE(stray_pixels(alias, layout), 20u) << "model pixels where no entity projects";
        }
        for (const Region& c : layout.candidates) {
            if (!checkable(c, layout)) continue;
            size_t own = count_pixels(c, layout).own;
            if (!best || own > best->own) best = Candidate{frame, c, layout, own};
        }
    }
    EXPECT_GE(frames_checked, 3u) << "too few frames to check every model's place";
    ASSERT_TRUE(best) << "no alias entity stands alone and unoccluded in any screenshot frame";

    SCOPED_TRACE("demo frame " + std::to_string(best->frame) + ", " + describe(best->region));
    RgbImage alias, classic;
    ASSERT_NO_FATAL_FAILURE(
        load_screenshot(engine_runs::shot(alias_run.dir, "alias", best->frame), alias));
    ASSERT_NO_FATAL_FAILURE(
        load_screenshot(engine_runs::shot(classic_run.dir, "classic", best->frame), classic));
    PixelCounts c = count_pixels(best->region, best->layout, &alias, &classic);
    EXPECT_GE(c.lit_own, c.own / 4) << "the model is not drawn there";
    EXPECT_LE(c.lit_ring, c.lit_own / 50) << "the model spills outside where it projects";
    EXPECT_GE(c.matching_classic, c.lit_own / 2)
        << "the classic renderer does not show the same model pixels there";
}

// ------------------------------------------------------------------ the showroom without data

TEST(EngineScreenshot, ShowroomWithoutDataShowsFourColouredModelsOnACheckerboard) {
    TempDir dir("nq_engine_showroom");
    std::string empty = dir.subdir("empty");
    auto args = engine_runs::base_args(dir.path(), empty, "");
    engine_runs::add(args, {"+wait", "+wait", "+screenshot", dir.file("x.png"), "+quit"});
    ProcessResult r = run_nprquake(args, dir.path(), 60);
    expect_clean_exit(r);
    EXPECT_NE(r.out.find("showroom"), std::string::npos) << r.out;
    RgbImage image;
    ASSERT_NO_FATAL_FAILURE(load_screenshot(dir.file("x.png"), image));

    expect_showroom_colours(image);

    // The floor fills the bottom rows: greys only, in two shades that alternate across a row.
    for (int y : {kHeight - 2, kHeight - 20}) {
        SCOPED_TRACE("row " + std::to_string(y));
        float lo = 255, hi = 0;
        for (int x = 0; x < kWidth; ++x) {
            Rgb c = pixel(image, x, y);
            EXPECT_LE(std::max({c[0], c[1], c[2]}) - std::min({c[0], c[1], c[2]}), 12)
                << "not grey at x " << x;
            lo = std::min(lo, luminance(c)), hi = std::max(hi, luminance(c));
        }
        EXPECT_GT(hi - lo, 25.0f) << "one shade only";
        float middle = (lo + hi) / 2;
        int changes = 0;
        bool light = luminance(pixel(image, 0, y)) > middle;
        for (int x = 1; x < kWidth; ++x) {
            bool now = luminance(pixel(image, x, y)) > middle;
            changes += now != light;
            light = now;
        }
        EXPECT_GE(changes, 4) << "the shades do not alternate";
    }
}

}  // namespace
}  // namespace nq
