// The `technical` plugin in the running engine, judged on its screenshots: on the showroom (a
// fixed showroom_time, so every shot shows the same instant) and on paused demo frames, each
// setting is compared with an object-id reference taken in the same run (tech_shading 3: every
// alias entity flat in a pure colour chosen by its number, no edges, no shadows):
//   - silhouettes cover the id outline (recall >= 95%) and add few pixels away from it;
//   - the cube's creases are ridges, the step's inner edge a valley;
//   - white addition w = 1 gives white edges, w = 0 the shaded colour; past the blend threshold
//     edges take the model colour;
//   - shadows darken the floor, never the models; penumbra off is one hard level.
// And both demos play to the end under technical, with classic <-> technical swaps mid-demo.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "support/engine_demo_replay.h"
#include "support/engine_image_checks.h"
#include "support/engine_output_checks.h"
#include "support/engine_runs.h"
#include "support/technical_image_checks.h"

namespace nq {
namespace {

using namespace test;
using namespace test::technical;

constexpr int kShowroomWidth = 640, kShowroomHeight = 480;
// The showroom's alias entities are numbered 2.. in the order cube, step, sphere, torus.
constexpr uint32_t kCube = 2, kStep = 3, kSphere = 4, kTorus = 5;
constexpr uint32_t kShowroomModels[] = {kCube, kStep, kSphere, kTorus};

// Settings, two frames to let them reach the screen, then a screenshot.
void shot_after(std::vector<std::string>& args, std::initializer_list<std::string> settings,
                const std::string& path) {
    args.insert(args.end(), settings);
    args.insert(args.end(), {"+wait", "+wait", "+screenshot", path});
}

// The reference's common settings: id shading, nothing drawn over the models.
const std::initializer_list<std::string> kReferenceSettings = {
    "+tech_shading",     "3", "+tech_silhouettes", "0", "+tech_creases", "0",
    "+tech_world_edges", "0", "+tech_shadows",     "0", "+tech_fade",    "0"};

const SharedRun& showroom_run() {
    return shared_nprquake_run("technical_showroom", [](const std::string& dir) {
        std::vector<std::string> args{"-userdir",
                                      dir + "/user",
                                      "-basedir",
                                      dir + "/nodata",
                                      "-width",
                                      std::to_string(kShowroomWidth),
                                      "-height",
                                      std::to_string(kShowroomHeight),
                                      "+con_notifytime",
                                      "0",
                                      "+r_plugin",
                                      "technical",
                                      "+showroom_time",
                                      "5",
                                      "+wait"};
        shot_after(args, kReferenceSettings, dir + "/reference.png");
        shot_after(args, {"+tech_silhouettes", "1", "+tech_edge_colors", "0"},
                   dir + "/silhouettes.png");
        shot_after(args, {"+tech_edge_colors", "2", "+tech_white", "1"}, dir + "/white1.png");
        shot_after(args, {"+tech_white", "0"}, dir + "/white0.png");
        shot_after(args, {"+tech_edge_colors", "0", "+tech_fade", "1", "+tech_fade_distance", "1"},
                   dir + "/faded.png");
        shot_after(args,
                   {"+tech_fade", "0", "+tech_silhouettes", "0", "+tech_creases", "1",
                    "+tech_ridge_color", "1 0 0", "+tech_valley_color", "1 0.5 0"},
                   dir + "/creases.png");
        shot_after(args, {"+tech_creases", "0", "+tech_shadows", "1", "+tech_shadow_penumbra", "0"},
                   dir + "/hard_shadow.png");
        shot_after(args, {"+tech_shadow_penumbra", "1"}, dir + "/penumbra.png");
        args.push_back("+quit");
        return args;
    });
}

RgbImage load(const SharedRun& run, const std::string& name) {
    RgbImage image;
    load_screenshot(run.dir + "/" + name, image);
    return image;
}

Mask models_mask(const RgbImage& reference) {
    Mask all = mask_where(reference, [](int, int) { return false; });
    for (uint32_t n : kShowroomModels) all = mask_union(all, id_mask(reference, n));
    return all;
}

// The id regions' outlines, each model's own (two touching models both keep their border).
Mask id_outlines(const RgbImage& reference, std::initializer_list<uint32_t> numbers) {
    Mask all = mask_where(reference, [](int, int) { return false; });
    for (uint32_t n : numbers) all = mask_union(all, outline(id_mask(reference, n)));
    return all;
}

// Pixels an edge setting added: black in `edges`, not black in the reference.
Mask black_edge_pixels(const RgbImage& edges, const RgbImage& reference) {
    return quality::line_pixels(edges, reference);
}

// Share of the masked pixels of `image` that satisfy `predicate`.
double share_where(const RgbImage& image, const Mask& m, auto predicate) {
    size_t total = 0, hit = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            if (!m.at(x, y)) continue;
            ++total;
            hit += predicate(pixel(image, x, y));
        }
    }
    return total ? static_cast<double>(hit) / total : 0.0;
}

bool is_showroom_id_colour(const Rgb& c) {
    for (uint32_t n : kShowroomModels) {
        if (c == id_colour(n)) return true;
    }
    return false;
}

TEST(TechnicalShowroom, RunsCleanly) {
    const SharedRun& run = showroom_run();
    expect_clean_exit(run.result);
    EXPECT_FALSE(lines_containing(run.result.out, "renderer: technical").empty()) << run.result.out;
}

TEST(TechnicalShowroom, ReferenceShowsEveryModelInItsIdColour) {
    RgbImage reference = load(showroom_run(), "reference.png");
    for (uint32_t n : kShowroomModels) {
        EXPECT_GT(count(id_mask(reference, n)), 500u) << "entity " << n;
    }
}

TEST(TechnicalShowroom, SilhouettesCoverTheObjectIdOutline) {
    const SharedRun& run = showroom_run();
    RgbImage reference = load(run, "reference.png"), edges = load(run, "silhouettes.png");
    const Mask boundary = id_outlines(reference, {kCube, kStep, kSphere, kTorus});
    const Mask edge = black_edge_pixels(edges, reference);
    ASSERT_GT(count(edge), 200u);
    const double recall = share_near(boundary, edge, 1);
    const double stray = 1.0 - share_near(edge, boundary, 2);
    EXPECT_GE(recall, 0.95) << "outline pixels with a silhouette pixel within 1 px";
    EXPECT_LT(stray, 0.10) << "silhouette pixels farther than 2 px from any outline";
    RecordProperty("recall", std::to_string(recall));
    RecordProperty("stray", std::to_string(stray));
}

TEST(TechnicalShowroom, CubeCreasesAreRidgesAndTheStepHasAValley) {
    const SharedRun& run = showroom_run();
    RgbImage reference = load(run, "reference.png"), creases = load(run, "creases.png");
    const int w = reference.width, h = reference.height;
    const Rgb ridge{255, 0, 0}, valley{255, 128, 0};
    auto count_in = [&](const Box& box, const Rgb& colour) {
        size_t n = 0;
        for (int y = std::max(box.y0, 0); y <= std::min(box.y1, h - 1); ++y) {
            for (int x = std::max(box.x0, 0); x <= std::min(box.x1, w - 1); ++x) {
                n += near_colour(pixel(creases, x, y), colour, 2);
            }
        }
        return n;
    };
    const Box cube = bounding_box(id_mask(reference, kCube)).grown(2);
    const Box step = bounding_box(id_mask(reference, kStep)).grown(2);
    ASSERT_FALSE(cube.empty());
    ASSERT_FALSE(step.empty());
    EXPECT_GT(count_in(cube, ridge), 40u) << "the cube's edges are ridges";
    EXPECT_EQ(count_in(cube, valley), 0u) << "a cube has no concave edge";
    EXPECT_GT(count_in(step, valley), 5u) << "the step's inner edge is a valley";
    EXPECT_GT(count_in(step, ridge), 40u) << "the step's outer edges are ridges";
}

TEST(TechnicalShowroom, WhiteAdditionOneIsWhiteZeroIsTheShadedColour) {
    const SharedRun& run = showroom_run();
    RgbImage reference = load(run, "reference.png"), edges = load(run, "silhouettes.png");
    RgbImage white1 = load(run, "white1.png"), white0 = load(run, "white0.png");
    const Mask edge = black_edge_pixels(edges, reference);
    ASSERT_GT(count(edge), 200u);
    EXPECT_GE(share_where(white1, edge,
                          [](const Rgb& c) { return c[0] >= 250 && c[1] >= 250 && c[2] >= 250; }),
              0.95)
        << "w = 1: silhouettes white";
    // In id shading the shaded colour is the entity's id colour: w = 0 adds nothing to it.
    EXPECT_GE(share_where(white0, edge, is_showroom_id_colour), 0.95) << "w = 0: shaded colour";
}

TEST(TechnicalShowroom, EdgesBeyondTheBlendThresholdTakeTheModelColour) {
    const SharedRun& run = showroom_run();
    RgbImage reference = load(run, "reference.png"), edges = load(run, "silhouettes.png");
    RgbImage faded = load(run, "faded.png");
    const Mask edge = black_edge_pixels(edges, reference);
    ASSERT_GT(count(edge), 200u);
    // Every model is farther than the 1-unit threshold: where its black silhouettes lay over
    // the model, the model's own colour shows; nowhere is an edge still black. (An edge that
    // has fully taken the model colour changes nothing, so the renderer may skip it.)
    const Mask edge_on_models = mask_where(faded, [&](int x, int y) {
        return edge.at(x, y) && is_showroom_id_colour(pixel(reference, x, y));
    });
    ASSERT_GT(count(edge_on_models), 100u);
    EXPECT_GE(share_where(faded, edge_on_models, is_showroom_id_colour), 0.95);
    EXPECT_LT(share_where(faded, edge, [](const Rgb& c) { return is_black(c); }), 0.02);
}

// Per changed pixel: luminance with shadows / luminance without.
std::vector<double> shadow_ratios(const RgbImage& shadowed, const RgbImage& reference,
                                  const Mask& models, size_t& on_models) {
    std::vector<double> ratios;
    on_models = 0;
    for (int y = 0; y < reference.height; ++y) {
        for (int x = 0; x < reference.width; ++x) {
            const Rgb a = pixel(shadowed, x, y), b = pixel(reference, x, y);
            if (a == b) continue;
            if (models.at(x, y)) ++on_models;
            if (luminance(b) >= 20) ratios.push_back(luminance(a) / luminance(b));
        }
    }
    return ratios;
}

double share_in(const std::vector<double>& values, double low, double high) {
    size_t n = 0;
    for (double v : values) n += v >= low && v <= high;
    return values.empty() ? 0.0 : static_cast<double>(n) / values.size();
}

TEST(TechnicalShowroom, HardShadowDarkensTheFloorOnceAndNeverTheModels) {
    const SharedRun& run = showroom_run();
    RgbImage reference = load(run, "reference.png"), hard = load(run, "hard_shadow.png");
    size_t on_models = 0;
    const auto ratios = shadow_ratios(hard, reference, models_mask(reference), on_models);
    EXPECT_EQ(on_models, 0u) << "shadow pixels on a model";
    ASSERT_GT(ratios.size(), 300u) << "no shadow on the floor";
    // tech_shadow_alpha 0.5 in black: every shadow pixel is the floor at half its luminance,
    // once (overlapping triangles of the projection must not darken twice).
    EXPECT_GE(share_in(ratios, 0.44, 0.56), 0.95);
}

TEST(TechnicalShowroom, PenumbraAddsALighterFringeAroundADarkerUmbra) {
    const SharedRun& run = showroom_run();
    RgbImage reference = load(run, "reference.png"), soft = load(run, "penumbra.png");
    size_t on_models = 0;
    const auto ratios = shadow_ratios(soft, reference, models_mask(reference), on_models);
    EXPECT_EQ(on_models, 0u) << "shadow pixels on a model";
    ASSERT_GT(ratios.size(), 300u);
    // Fringe: one penumbra projection alone (alpha 0.2 -> 0.8). Core: umbra and both penumbrae.
    EXPECT_GE(share_in(ratios, 0.74, 0.86), 0.05) << "no lighter penumbra fringe";
    EXPECT_GE(share_in(ratios, 0.0, 0.45), 0.05) << "no darker umbra";
    EXPECT_LT(share_in(ratios, 1.0, 10.0), 0.01) << "shadows only darken";
}

// ------------------------------------------------------------------ demos

constexpr uint64_t kDemoPausedFrame = 760;  // the monster gallery (see engine_runs.h)

// demo.dem entirely under technical (at 640x480, so 2-pixel edges), with an id reference and
// silhouettes of one paused frame.
const SharedRun& demo_technical() {
    return shared_nprquake_run(
        "demo_technical",
        [](const std::string& dir) {
            std::vector<std::string> args{
                "-userdir",        dir + "/user", "-basedir",        data_root(),
                "-game",           "lq1",         "-width",          "640",
                "-height",         "480",         "+con_notifytime", "0",
                "+scr_centertime", "0",           "+r_plugin",       "technical"};
            // The renderer's picture alone: no status bar, no screen tints (engine_runs.h).
            engine_runs::add(args, {"+scr_drawhud", "0", "+gl_polyblend", "0"});
            const std::string reference =
                "tech_shading 3; tech_silhouettes 0; tech_creases 0; tech_world_edges 0; "
                "tech_shadows 0; tech_fade 0; tech_edge_colors 0";
            engine_runs::demo_at(args, kDemoPausedFrame,
                                 "pause 1; " + reference + "; wait; wait; screenshot " + dir +
                                     "/demo_reference.png; tech_silhouettes 1; wait; wait; "
                                     "screenshot " +
                                     dir + "/demo_silhouettes.png; pause 0");
            engine_runs::add(args, {"+timedemo", "demo", "+quit"});
            return args;
        },
        600);
}

TEST(TechnicalDemo, DemoPlaysToTheEndUnderTechnical) {
    expect_whole_timedemo(demo_technical(), "demo.dem");
}

TEST(TechnicalDemo, SilhouettesCoverTheOutlinesOfADemoFrame) {
    const SharedRun& run = demo_technical();
    RgbImage reference, edges;
    ASSERT_NO_FATAL_FAILURE(load_screenshot(run.dir + "/demo_reference.png", reference));
    ASSERT_NO_FATAL_FAILURE(load_screenshot(run.dir + "/demo_silhouettes.png", edges));
    // Every id colour present in the frame (entity numbers are not known here): the benchmark
    // report's measure (edgequality silhouettes).
    ASSERT_GT(count(quality::any_id_pixels(reference)), 2000u) << "no alias model in the frame";
    const quality::SilhouetteScore score = quality::score_silhouettes(reference, edges);
    const double recall = score.recall;
    // Away from the id outlines an edge is either an inner silhouette (a fold of the model in
    // front of itself, which an id image cannot show) or a mistake; off the models entirely it
    // can only be a mistake.
    const double off_outline = 1.0 - score.precision;
    const double off_models = 1.0 - score.on_models;
    EXPECT_GE(recall, 0.95);
    EXPECT_LT(off_outline, 0.30);
    EXPECT_LT(off_models, 0.01);
    RecordProperty("recall", std::to_string(recall));
    RecordProperty("off_outline", std::to_string(off_outline));
    RecordProperty("off_models", std::to_string(off_models));
}

// demo2.dem under technical, swapped to classic and back mid-demo (also to the plugin already
// running), screenshots of each style on one paused frame.
const SharedRun& demo2_technical_swaps() {
    return shared_nprquake_run(
        "demo2_technical_swaps",
        [](const std::string& dir) {
            auto args = engine_runs::base_args(dir, data_root(), "lq1");
            engine_runs::add(args, {"+r_plugin", "technical"});
            engine_runs::demo_at(args, 500,
                                 "pause 1; wait; wait; screenshot " + dir +
                                     "/technical.png; r_plugin classic; wait; wait; "
                                     "screenshot " +
                                     dir + "/classic.png; pause 0");
            engine_runs::demo_at(args, 900, "r_plugin technical");
            // Swapping to the plugin already running loads the same library image again.
            engine_runs::demo_at(args, 1200, "r_plugin technical; wait; r_plugin classic");
            engine_runs::demo_at(args, 1300, "r_plugin classic; wait; r_plugin technical");
            engine_runs::add(args, {"+timedemo", "demo2", "+quit"});
            return args;
        },
        600);
}

TEST(TechnicalDemo, Demo2PlaysToTheEndWithSwapsBothWays) {
    const SharedRun& run = demo2_technical_swaps();
    ASSERT_NO_FATAL_FAILURE(expect_whole_timedemo(run, "demo2.dem"));
    EXPECT_TRUE(lines_containing(run.result.out, "keeping").empty()) << run.result.out;

    RgbImage technical, classic;
    ASSERT_NO_FATAL_FAILURE(load_screenshot(run.dir + "/technical.png", technical));
    ASSERT_NO_FATAL_FAILURE(load_screenshot(run.dir + "/classic.png", classic));
    // The same paused frame in both styles: the world (classic textures underneath) mostly
    // agrees; technical adds its edges and shading, so the pictures differ.
    size_t differing = 0;
    for (int y = 0; y < technical.height; ++y) {
        for (int x = 0; x < technical.width; ++x) {
            differing += !near_colour(pixel(technical, x, y), pixel(classic, x, y), 8);
        }
    }
    const double share = static_cast<double>(differing) / (technical.width * technical.height);
    EXPECT_GT(share, 0.01) << "technical drew nothing of its own";
    EXPECT_LT(share, 0.9) << "the world should still be the same place";
    EXPECT_GT(region_stats(technical, whole(technical)).luminance_stddev, 12.0);
}

}  // namespace
}  // namespace nq
