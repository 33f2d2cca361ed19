// The model cache: start.bsp as the world with its inline submodels (ranges and bounds checked
// against the raw models lump), ids in request order, alias/sprite/standalone brush models,
// missing and broken models as placeholders with warnings; a model's kind told by its first bytes,
// not its name.
#include <gtest/gtest.h>

#include <map>

#include "render/model_cache.h"
#include "render/placeholder_model.h"
#include "support/render_test_support.h"

namespace nq {
namespace {

using render_test::raw_f32;
using render_test::raw_i32;

bool any_warning_names(const std::vector<std::string>& warnings, const std::string& text) {
    for (const std::string& w : warnings) {
        if (w.find(text) != std::string::npos) return true;
    }
    return false;
}

TEST(RenderModelCache, WorldAndItsSubmodelsTakeTheFirstIds) {
    ModelCache cache(render_test::lq1_reader());
    auto world = cache.load_world("maps/start.bsp");
    ASSERT_TRUE(world) << world.error().to_string();
    EXPECT_EQ(*world, 1u);
    ASSERT_NE(cache.world(), nullptr);
    EXPECT_EQ(cache.world()->kind(), uint32_t{NQR_MODEL_BRUSH});

    // The models lump (14) of BSP29: 64-byte records, mins at 0, maxs at 12, first face at 56,
    // face count at 60.
    const std::vector<uint8_t> raw = render_test::lq1_bytes("maps/start.bsp");
    const size_t lump = size_t(raw_i32(raw, 4 + 8 * 14));
    const size_t count = size_t(raw_i32(raw, 8 + 8 * 14)) / 64;
    ASSERT_EQ(count, 9u);
    ASSERT_EQ(cache.models().size(), count);
    const nqr_brush_model* shared = cache.world()->abi()->brush;
    for (size_t i = 0; i < count; ++i) {
        const std::string name = i == 0 ? "maps/start.bsp" : "*" + std::to_string(i);
        const nqr_model_id id = cache.find(name);
        ASSERT_EQ(id, i + 1) << name;
        const nqr_model& m = *cache.get(id)->abi();
        EXPECT_EQ(m.size, sizeof(nqr_model));
        EXPECT_EQ(m.id, id);
        EXPECT_EQ(m.kind, uint32_t{NQR_MODEL_BRUSH});
        EXPECT_STREQ(m.name, name.c_str());
        EXPECT_EQ(m.brush, shared) << "submodels share the world's brush data";
        const size_t at = lump + 64 * i;
        EXPECT_EQ(m.first_surface, uint32_t(raw_i32(raw, at + 56))) << name;
        EXPECT_EQ(m.num_surfaces, uint32_t(raw_i32(raw, at + 60))) << name;
        for (int c = 0; c < 3; ++c) {
            EXPECT_EQ(m.mins[c], raw_f32(raw, at + 4 * c));
            EXPECT_EQ(m.maxs[c], raw_f32(raw, at + 12 + 4 * c));
            EXPECT_GE(m.radius, std::max(std::fabs(m.mins[c]), std::fabs(m.maxs[c])));
        }
        EXPECT_LE(m.first_surface + m.num_surfaces, m.brush->num_surfaces);
    }
    // Asking for a submodel again gives its id; asking for the world by name too.
    EXPECT_EQ(cache.load("*3"), 4u);
    EXPECT_EQ(cache.load("maps/start.bsp"), 1u);
    EXPECT_EQ(cache.models().size(), count);
}

TEST(RenderModelCache, OtherModelsGetIdsInRequestOrderAndKeepThem) {
    ModelCache cache(render_test::lq1_reader());
    ASSERT_TRUE(cache.load_world("maps/start.bsp"));
    const nqr_model_id player = cache.load("progs/player.mdl");
    const nqr_model_id explosion = cache.load("progs/s_explod.spr");
    const nqr_model_id battery = cache.load("maps/b_batt0.bsp");
    EXPECT_EQ(player, 10u);
    EXPECT_EQ(explosion, 11u);
    EXPECT_EQ(battery, 12u);
    EXPECT_EQ(cache.load("progs/player.mdl"), player);
    EXPECT_EQ(cache.find("PROGS/Player.MDL"), player) << "names are case-insensitive";
    EXPECT_EQ(cache.find("progs/ogre.mdl"), 0u);

    const nqr_model& p = *cache.get(player)->abi();
    EXPECT_EQ(p.kind, uint32_t{NQR_MODEL_ALIAS});
    ASSERT_NE(p.alias, nullptr);
    EXPECT_GT(p.alias->num_frames, 0u);
    EXPECT_FALSE(cache.get(player)->placeholder());
    // The player stands 56 units tall around its origin (-24 .. 32 in Quake's hull); its mesh
    // lies within a generous box around that.
    EXPECT_LT(p.mins[2], -20.0f);
    EXPECT_GT(p.maxs[2], 20.0f);

    const nqr_model& s = *cache.get(explosion)->abi();
    EXPECT_EQ(s.kind, uint32_t{NQR_MODEL_SPRITE});
    ASSERT_NE(s.sprite, nullptr);
    EXPECT_GT(s.sprite->num_frames, 1u);

    const nqr_model& b = *cache.get(battery)->abi();
    EXPECT_EQ(b.kind, uint32_t{NQR_MODEL_BRUSH});
    EXPECT_NE(b.brush, cache.world()->abi()->brush) << "an item box is its own map";
    EXPECT_EQ(b.first_surface, 0u);
    EXPECT_EQ(b.num_surfaces, b.brush->num_surfaces);
    EXPECT_EQ(cache.get(0), nullptr);
    EXPECT_EQ(cache.get(99), nullptr);
}

TEST(RenderModelCache, MissingModelsArePlaceholdersWithAWarning) {
    ModelCache cache(render_test::lq1_reader());
    ASSERT_TRUE(cache.load_world("maps/start.bsp"));
    (void)cache.take_warnings();
    for (const std::string name :
         {"progs/h_nosuch.mdl", "progs/nosuch.spr", "maps/b_nosuch.bsp", "*42", "progs/odd.wav"}) {
        const nqr_model_id id = cache.load(name);
        ASSERT_NE(id, 0u) << name;
        const RenderModel* m = cache.get(id);
        EXPECT_TRUE(m->placeholder()) << name;
        EXPECT_EQ(m->kind(), uint32_t{NQR_MODEL_ALIAS});
        EXPECT_EQ(m->abi()->alias->skins->images[0][0], kPlaceholderColor);
        EXPECT_STREQ(m->abi()->name, name.c_str());
        EXPECT_EQ(cache.load(name), id) << "the placeholder keeps the name's id";
        const auto warnings = cache.take_warnings();
        EXPECT_TRUE(any_warning_names(warnings, name)) << name;
        EXPECT_TRUE(any_warning_names(warnings, "placeholder")) << name;
    }
}

TEST(RenderModelCache, BrokenFileIsAPlaceholderNamingTheProblem) {
    ModelCache cache([](const std::string& path) -> Result<std::vector<uint8_t>> {
        return std::vector<uint8_t>{'I', 'D', 'P', 'O', 6, 0, 0, 0};  // truncated header
    });
    const nqr_model_id id = cache.load("progs/broken.mdl");
    EXPECT_TRUE(cache.get(id)->placeholder());
    EXPECT_TRUE(any_warning_names(cache.take_warnings(), "progs/broken.mdl"));
}

// A reader that serves real files under other names: misnamed models, as mods ship them.
ModelCache::FileReader renaming_reader(std::map<std::string, std::string> served_as) {
    return [served_as, real = render_test::lq1_reader()](const std::string& path) {
        const auto it = served_as.find(path);
        return real(it == served_as.end() ? path : it->second);
    };
}

TEST(RenderModelCache, AModelsKindComesFromItsBytesNotItsName) {
    ModelCache cache(renaming_reader({{"progs/explosion.mdl", "progs/s_explod.spr"},
                                      {"progs/player.bsp", "progs/player.mdl"},
                                      {"progs/box.spr", "maps/b_batt0.bsp"}}));
    const std::vector<std::pair<std::string, uint32_t>> cases = {
        {"progs/explosion.mdl", NQR_MODEL_SPRITE},
        {"progs/player.bsp", NQR_MODEL_ALIAS},
        {"progs/box.spr", NQR_MODEL_BRUSH}};
    for (const auto& [name, kind] : cases) {
        const RenderModel* m = cache.get(cache.load(name));
        ASSERT_NE(m, nullptr) << name;
        EXPECT_FALSE(m->placeholder()) << name;
        EXPECT_EQ(m->kind(), kind) << name;
        const auto warnings = cache.take_warnings();
        EXPECT_TRUE(any_warning_names(warnings, name + ": its content is a")) << name;
    }
    // The same content as under its own name: the sprite's frames, the model's frames.
    ModelCache proper(render_test::lq1_reader());
    EXPECT_EQ(cache.get(cache.find("progs/explosion.mdl"))->abi()->sprite->num_frames,
              proper.get(proper.load("progs/s_explod.spr"))->abi()->sprite->num_frames);
    EXPECT_EQ(cache.get(cache.find("progs/player.bsp"))->abi()->alias->num_frames,
              proper.get(proper.load("progs/player.mdl"))->abi()->alias->num_frames);
    EXPECT_FALSE(any_warning_names(proper.take_warnings(), "its content is a"))
        << "a rightly named model warns of nothing";
}

TEST(RenderModelCache, AFileThatIsNoModelIsAPlaceholderNamingItsFirstBytes) {
    const std::string wav = "sound/weapons/sgun1.wav";
    ModelCache cache(renaming_reader({{"progs/shotgun.mdl", wav}}));
    const RenderModel* m = cache.get(cache.load("progs/shotgun.mdl"));
    ASSERT_NE(m, nullptr);
    EXPECT_TRUE(m->placeholder());
    const std::vector<uint8_t> raw = render_test::lq1_bytes(wav);
    ASSERT_GE(raw.size(), 4u);
    const std::string magic(raw.begin(), raw.begin() + 4);  // "RIFF" in any WAV
    EXPECT_TRUE(any_warning_names(
        cache.take_warnings(),
        "progs/shotgun.mdl: offset 0: not a model (first bytes \"" + magic + "\""));
}

TEST(RenderModelCache, UnprintableOrNoFirstBytesAreNamedInHexOrAsEmpty) {
    ModelCache cache([](const std::string& path) -> Result<std::vector<uint8_t>> {
        if (path == "progs/empty.mdl") return std::vector<uint8_t>{};
        return std::vector<uint8_t>{0x1f, 0x8b, 0x08, 0x00, 0x11};  // a gzip header
    });
    EXPECT_TRUE(cache.get(cache.load("progs/packed.mdl"))->placeholder());
    EXPECT_TRUE(any_warning_names(cache.take_warnings(), "(first bytes 1f 8b 08 00;"));
    EXPECT_TRUE(cache.get(cache.load("progs/empty.mdl"))->placeholder());
    EXPECT_TRUE(any_warning_names(cache.take_warnings(), "not a model (an empty file;"));
}

TEST(RenderModelCache, MissingWorldFailsAndNewWorldRestartsIds) {
    ModelCache cache(render_test::lq1_reader());
    ASSERT_TRUE(cache.load_world("maps/start.bsp"));
    cache.load("progs/player.mdl");
    auto missing = cache.load_world("maps/nosuch.bsp");
    ASSERT_FALSE(missing);
    EXPECT_NE(missing.error().to_string().find("maps/nosuch.bsp"), std::string::npos);
    EXPECT_TRUE(cache.models().empty());
    EXPECT_EQ(cache.world(), nullptr);

    auto world = cache.load_world("maps/lqdm4_a6.bsp");
    ASSERT_TRUE(world);
    EXPECT_EQ(*world, 1u);
    EXPECT_EQ(cache.find("progs/player.mdl"), 0u);
    EXPECT_EQ(cache.models().size(), 6u);  // the world and five inline models
}

TEST(RenderModelCache, SubmodelWithoutWorldIsAPlaceholder) {
    ModelCache cache(render_test::lq1_reader());
    const nqr_model_id id = cache.load("*1");
    EXPECT_TRUE(cache.get(id)->placeholder());
    EXPECT_TRUE(any_warning_names(cache.take_warnings(), "no world"));
}

}  // namespace
}  // namespace nq
