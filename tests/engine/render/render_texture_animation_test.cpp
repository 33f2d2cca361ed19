// Animation chains resolved from texture names: primary digit chains, alternate letter chains
// (either case), gaps that cut a chain, chains missing frame 0, duplicates, still textures.
#include <gtest/gtest.h>

#include "render/brush_textures.h"
#include "render/texture_animation.h"

namespace nq {
namespace {

TextureAnimations resolve(const std::vector<std::string_view>& names) {
    return resolve_texture_animations(names);
}

bool has_warning(const TextureAnimations& a, const std::string& text) {
    for (const std::string& w : a.warnings) {
        if (w.find(text) != std::string::npos) return true;
    }
    return false;
}

using Chain = std::vector<int32_t>;

TEST(RenderTextureAnimation, DigitChainInFrameOrderWhateverTheStorageOrder) {
    const auto a = resolve({"+2lava", "wall", "+0lava", "+1lava"});
    EXPECT_EQ(a.per_texture[0].frames, (Chain{2, 3, 0}));
    EXPECT_EQ(a.per_texture[2].frames, (Chain{2, 3, 0}));
    EXPECT_EQ(a.per_texture[3].frames, (Chain{2, 3, 0}));
    EXPECT_TRUE(a.per_texture[1].frames.empty());
    EXPECT_TRUE(a.per_texture[0].alternate.empty());
    EXPECT_TRUE(a.warnings.empty());
}

TEST(RenderTextureAnimation, LetterChainIsTheAlternateOfTheDigitChainAndViceVersa) {
    const auto a = resolve({"+0btn", "+1btn", "+abtn", "+Bbtn"});
    EXPECT_EQ(a.per_texture[0].frames, (Chain{0, 1}));
    EXPECT_EQ(a.per_texture[0].alternate, (Chain{2, 3}));
    EXPECT_EQ(a.per_texture[3].frames, (Chain{2, 3}));
    EXPECT_EQ(a.per_texture[3].alternate, (Chain{0, 1}));
}

TEST(RenderTextureAnimation, ChainsWithDifferentBaseNamesStayApart) {
    const auto a = resolve({"+0a", "+0b", "+1a"});
    EXPECT_EQ(a.per_texture[0].frames, (Chain{0, 2}));
    EXPECT_EQ(a.per_texture[1].frames, (Chain{1}));
}

TEST(RenderTextureAnimation, GapCutsTheChainWithAWarning) {
    const auto a = resolve({"+0x", "+1x", "+3x"});
    EXPECT_EQ(a.per_texture[0].frames, (Chain{0, 1}));
    EXPECT_TRUE(a.per_texture[2].frames.empty());
    EXPECT_TRUE(has_warning(a, "+3x follows missing frame +2x")) << a.warnings.size();
}

TEST(RenderTextureAnimation, ChainWithoutFrameZeroIsStillWithAWarning) {
    const auto a = resolve({"+1x", "+2x"});
    EXPECT_TRUE(a.per_texture[0].frames.empty());
    EXPECT_TRUE(a.per_texture[1].frames.empty());
    EXPECT_TRUE(has_warning(a, "+1x follows missing frame +0x"));
}

TEST(RenderTextureAnimation, RepeatedNameKeepsTheFirstWithAWarning) {
    const auto a = resolve({"+0x", "+0x", "+1x"});
    EXPECT_EQ(a.per_texture[0].frames, (Chain{0, 2}));
    EXPECT_TRUE(a.per_texture[1].frames.empty());
    EXPECT_TRUE(has_warning(a, "+0x appears twice"));
}

TEST(RenderTextureAnimation, TenFramesEachWayAndNothingBeyond) {
    std::vector<std::string> storage;
    for (char c = '0'; c <= '9'; ++c) storage.push_back(std::string("+") + c + "t");
    for (char c = 'a'; c <= 'j'; ++c) storage.push_back(std::string("+") + c + "t");
    storage.push_back("+kt");  // not a frame name: a still texture
    std::vector<std::string_view> names(storage.begin(), storage.end());
    const auto a = resolve_texture_animations(names);
    EXPECT_EQ(a.per_texture[0].frames.size(), 10u);
    EXPECT_EQ(a.per_texture[0].alternate.size(), 10u);
    EXPECT_EQ(a.per_texture[19].frames.front(), 10);
    EXPECT_TRUE(a.per_texture[20].frames.empty());
}

TEST(RenderTextureAnimation, NamesTooShortOrNotPlusAreStill) {
    const auto a = resolve({"+0", "0abc", "*water", "+"});
    for (const TextureAnimation& t : a.per_texture) EXPECT_TRUE(t.frames.empty());
}

TEST(RenderTextureAnimation, FlagsFromNames) {
    EXPECT_EQ(texture_flags_for_name("sky1"), uint32_t{NQR_TEXTURE_SKY});
    EXPECT_EQ(texture_flags_for_name("SKY4"), uint32_t{NQR_TEXTURE_SKY});
    EXPECT_EQ(texture_flags_for_name("*lava1"), uint32_t{NQR_TEXTURE_LIQUID});
    EXPECT_EQ(texture_flags_for_name("+0sky"), 0u);
    EXPECT_EQ(texture_flags_for_name(""), 0u);
}

}  // namespace
}  // namespace nq
