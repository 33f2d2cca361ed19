// nprlib/gl: program building and its errors, uniform caching, RAII owners and their tracker,
// palette image conversion, texture upload with mipmaps, and the streaming ring buffer.
#include <gtest/gtest.h>

#include <cstring>
#include <numeric>

#include "gl/handles.h"
#include "gl/palette_image.h"
#include "gl/program.h"
#include "gl/stream_buffer.h"
#include "gl/texture_upload.h"
#include "support/nprlib_test_support.h"

namespace nq::npr::test {
namespace {

using namespace nq::npr::gl;

// ------------------------------------------------------------------ CPU: palette images

TEST(PaletteImage, ExpandsIndicesThroughThePalette) {
    const auto palette = make_test_palette();
    const std::vector<uint8_t> pixels = {colour::kRed, 0, colour::kTransparent};
    std::vector<uint8_t> rgba;
    expand_palette_image(pixels, palette.data(), {}, rgba);
    EXPECT_EQ(rgba, (std::vector<uint8_t>{120, 30, 20, 255, 0, 0, 0, 255, 255, 0, 255, 255}));
}

TEST(PaletteImage, Index255IsTransparentForSpritesAndIndex0ForTheSkyFront) {
    const auto palette = make_test_palette();
    const std::vector<uint8_t> pixels = {colour::kRed, 0, 255};
    std::vector<uint8_t> rgba;
    expand_palette_image(pixels, palette.data(), {.transparent = Transparent::index255}, rgba);
    EXPECT_EQ(rgba[3], 255);
    EXPECT_EQ(rgba[7], 255);
    EXPECT_EQ(rgba[11], 0);
    expand_palette_image(pixels, palette.data(), {.transparent = Transparent::index0}, rgba);
    EXPECT_EQ(rgba[7], 0);
    EXPECT_EQ(rgba[11], 255);
}

TEST(PaletteImage, FullbrightRangeIs224To254) {
    EXPECT_FALSE(is_fullbright_index(223));
    EXPECT_TRUE(is_fullbright_index(224));
    EXPECT_TRUE(is_fullbright_index(254));
    EXPECT_FALSE(is_fullbright_index(255));
    EXPECT_TRUE(has_fullbright_pixels(std::vector<uint8_t>{1, 2, 230}));
    EXPECT_FALSE(has_fullbright_pixels(std::vector<uint8_t>{1, 2, 255}));
}

TEST(PaletteImage, FullbrightMaskAndBlackenedBaseSplitTheImage) {
    const auto palette = make_test_palette();
    const std::vector<uint8_t> pixels = {colour::kFullbrightGreen, colour::kRed};
    std::vector<uint8_t> mask, base;
    extract_fullbright_mask(pixels, palette.data(), mask);
    EXPECT_EQ(mask, (std::vector<uint8_t>{0, 250, 0, 255, 0, 0, 0, 0}));
    expand_palette_image(pixels, palette.data(), {.blacken_fullbrights = true}, base);
    EXPECT_EQ(base, (std::vector<uint8_t>{0, 0, 0, 255, 120, 30, 20, 255}));
}

TEST(PaletteImage, TransparentTexelsTakeTheirOpaqueNeighboursColour) {
    // 3 x 1: red, clear, blue (wrapping: the clear texel's neighbours are red and blue).
    std::vector<uint8_t> rgba = {100, 0, 0, 255, 9, 9, 9, 0, 0, 0, 200, 255};
    bleed_colour_into_transparent_texels(rgba, 3, 1);
    EXPECT_EQ(rgba[4], 50);
    EXPECT_EQ(rgba[5], 0);
    EXPECT_EQ(rgba[6], 100);
    EXPECT_EQ(rgba[7], 0);  // still transparent
}

// ------------------------------------------------------------------ GL

class GlHelpersTest : public GlSuiteTest<GlHelpersTest> {
  protected:
    void TearDown() override {
        EXPECT_EQ(tracker_.total_live(), 0);
        EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    }

    ObjectTracker tracker_;
};

constexpr const char* kVertex = R"(#version 330 core
layout(location = 0) in vec3 a_position;
uniform mat4 u_matrix;
out vec3 v_colour;
void main() { gl_Position = u_matrix * vec4(a_position, 1.0); v_colour = a_position; }
)";
constexpr const char* kFragment = R"(#version 330 core
in vec3 v_colour;
uniform vec3 u_tint;
out vec4 o_colour;
void main() { o_colour = vec4(v_colour * u_tint, 1.0); }
)";

TEST_F(GlHelpersTest, CompileErrorNamesProgramStageAndCarriesTheInfoLog) {
    ProgramBuild build = Program::build(
        {"broken", kVertex, "#version 330 core\nvoid main() { nope; }\n"}, &tracker_);
    EXPECT_FALSE(build.ok());
    EXPECT_FALSE(build.program);
    EXPECT_NE(build.error.find("broken"), std::string::npos) << build.error;
    EXPECT_NE(build.error.find("fragment shader failed to compile"), std::string::npos);
    EXPECT_NE(build.error.find("nope"), std::string::npos) << build.error;  // the driver's log
}

TEST_F(GlHelpersTest, LinkErrorIsReported) {
    // The fragment stage declares v_colour with another type than the vertex stage writes.
    const char* fragment =
        "#version 330 core\nin vec4 v_colour;\nout vec4 o;\n"
        "void main() { o = v_colour; }\n";
    ProgramBuild build = Program::build({"unlinked", kVertex, fragment}, &tracker_);
    EXPECT_FALSE(build.ok());
    EXPECT_NE(build.error.find("failed to link"), std::string::npos) << build.error;
}

TEST_F(GlHelpersTest, UniformLocationsAreCachedAndMissingOnesAreMinusOne) {
    ProgramBuild build = Program::build({"ok", kVertex, kFragment}, &tracker_);
    ASSERT_TRUE(build.ok()) << build.error;
    Program& program = build.program;
    EXPECT_EQ(tracker_.live(ObjectKind::program), 1);
    EXPECT_EQ(tracker_.live(ObjectKind::shader), 0);  // stages freed after linking
    const GLint tint = program.location("u_tint");
    EXPECT_EQ(tint, glGetUniformLocation(program.id(), "u_tint"));
    EXPECT_GE(tint, 0);
    EXPECT_EQ(program.location("u_tint"), tint);
    EXPECT_EQ(program.location("u_absent"), -1);
    EXPECT_EQ(program.location("u_absent"), -1);
    EXPECT_NE(program.location("u_matrix"), tint);
}

TEST_F(GlHelpersTest, OwnersDeleteTheirObjectsAndMoveOwnership) {
    GLuint name = 0;
    {
        Buffer buffer = Buffer::create(&tracker_);
        name = buffer.id();
        glBindBuffer(GL_ARRAY_BUFFER, name);  // a name becomes an object when first bound
        glBindBuffer(GL_ARRAY_BUFFER, 0);
        EXPECT_TRUE(glIsBuffer(name));
        EXPECT_EQ(tracker_.live(ObjectKind::buffer), 1);
        Buffer moved = std::move(buffer);
        EXPECT_FALSE(buffer);  // NOLINT(bugprone-use-after-move): checking the moved-from state
        EXPECT_EQ(moved.id(), name);
        EXPECT_EQ(tracker_.live(ObjectKind::buffer), 1);
    }
    EXPECT_FALSE(glIsBuffer(name));
    EXPECT_EQ(tracker_.live(ObjectKind::buffer), 0);
    EXPECT_EQ(tracker_.created(ObjectKind::buffer), 1);

    Texture a = Texture::create(&tracker_);
    Texture b = Texture::create(&tracker_);
    const GLuint b_name = b.id();
    a = std::move(b);  // a's old texture is deleted, b's is kept
    EXPECT_EQ(a.id(), b_name);
    EXPECT_EQ(tracker_.live(ObjectKind::texture), 1);
    VertexArray vao = VertexArray::create(&tracker_);
    Framebuffer fbo = Framebuffer::create(&tracker_);
    EXPECT_EQ(tracker_.total_live(), 3);
    a.reset();
    vao.reset();
    fbo.reset();
}

TEST_F(GlHelpersTest, PaletteTextureUploadsExactColoursWithMipmaps) {
    const auto palette = make_test_palette();
    const std::vector<uint8_t> pixels =
        make_image(16, 16, [](int x, int y) { return (x + y) % 2 ? colour::kRed : colour::kBlue; });
    std::vector<uint8_t> scratch;
    Texture texture = create_palette_texture(&tracker_, 16, 16, pixels, palette.data(), {},
                                             kMipmappedRepeat, scratch);
    glBindTexture(GL_TEXTURE_2D, texture.id());
    std::vector<uint8_t> level0(16 * 16 * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, level0.data());
    std::vector<uint8_t> expected;
    expand_palette_image(pixels, palette.data(), {}, expected);
    EXPECT_EQ(level0, expected);
    GLint width2 = 0, min_filter = 0;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 2, GL_TEXTURE_WIDTH, &width2);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &min_filter);
    EXPECT_EQ(width2, 4);                            // the mip chain exists
    EXPECT_EQ(min_filter, GL_LINEAR_MIPMAP_LINEAR);  // QuakeSpasm's default texture mode
    // The 1x1 level averages the checkerboard: half red, half blue.
    uint8_t level4[4] = {};
    glGetTexImage(GL_TEXTURE_2D, 4, GL_RGBA, GL_UNSIGNED_BYTE, level4);
    EXPECT_NEAR(level4[0], (120 + 20) / 2, 2);
    EXPECT_NEAR(level4[2], (20 + 110) / 2, 2);
    glBindTexture(GL_TEXTURE_2D, 0);
}

TEST_F(GlHelpersTest, FullbrightTextureOnlyWhenThereAreFullbrightPixels) {
    const auto palette = make_test_palette();
    std::vector<uint8_t> scratch;
    const std::vector<uint8_t> plain(16, colour::kRed);
    EXPECT_FALSE(create_fullbright_texture(&tracker_, 4, 4, plain, palette.data(), kMipmappedRepeat,
                                           scratch));
    std::vector<uint8_t> bright = plain;
    bright[5] = colour::kFullbrightGreen;
    EXPECT_TRUE(create_fullbright_texture(&tracker_, 4, 4, bright, palette.data(), kMipmappedRepeat,
                                          scratch));
}

std::vector<uint8_t> read_buffer(GLuint buffer, size_t offset, size_t bytes) {
    std::vector<uint8_t> out(bytes);
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    glGetBufferSubData(GL_ARRAY_BUFFER, static_cast<GLintptr>(offset),
                       static_cast<GLsizeiptr>(bytes), out.data());
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    return out;
}

void exercise_stream(StreamBuffer& stream) {
    std::vector<uint8_t> data(1000);
    std::iota(data.begin(), data.end(), 0);
    size_t previous_end = 0;
    int wraps_seen = 0;
    for (int i = 0; i < 40; ++i) {  // 40 KB through a 16 KB ring: it must wrap
        data[0] = static_cast<uint8_t>(i);
        const size_t offset = stream.push(data.data(), data.size(), 64);
        ASSERT_NE(offset, StreamBuffer::kNoSpace);
        EXPECT_EQ(offset % 64, 0u);
        EXPECT_LE(offset + data.size(), stream.capacity());
        if (stream.wraps() == wraps_seen) {
            EXPECT_GE(offset, previous_end);  // moves forward until it wraps
        }
        wraps_seen = stream.wraps();
        previous_end = offset + data.size();
        glFinish();
        EXPECT_EQ(read_buffer(stream.id(), offset, data.size()), data) << i;
    }
    EXPECT_GE(stream.wraps(), 2);
    std::vector<uint8_t> too_big(stream.max_push() + 1);
    EXPECT_EQ(stream.push(too_big.data(), too_big.size()), StreamBuffer::kNoSpace);
}

TEST_F(GlHelpersTest, PersistentStreamBufferRingsAndFences) {
    if (!context_supports_buffer_storage()) GTEST_SKIP() << "no GL 4.4 buffer storage";
    StreamBuffer stream;
    ASSERT_TRUE(stream.create(&tracker_, 16 * 1024, StreamBuffer::Mode::persistent));
    EXPECT_EQ(stream.mode(), StreamBuffer::Mode::persistent);
    EXPECT_EQ(stream.max_push(), stream.capacity() / StreamBuffer::kRegions);
    exercise_stream(stream);
    EXPECT_GT(tracker_.created(ObjectKind::sync), 0);
    stream.reset();
    EXPECT_EQ(tracker_.live(ObjectKind::sync), 0);
}

TEST_F(GlHelpersTest, OrphaningStreamBufferRings) {
    StreamBuffer stream;
    ASSERT_TRUE(stream.create(&tracker_, 16 * 1024, StreamBuffer::Mode::orphaning));
    EXPECT_EQ(stream.mode(), StreamBuffer::Mode::orphaning);
    exercise_stream(stream);
}

// Region starts are multiples of kGranularity, so only its divisors can be promised there; a
// 32-byte record pushed right after a 40-byte one still starts on a multiple of 32.
TEST_F(GlHelpersTest, StreamBufferAlignsToDivisorsOfItsGranularityOnly) {
    for (StreamBuffer::Mode mode : {StreamBuffer::Mode::automatic, StreamBuffer::Mode::orphaning}) {
        StreamBuffer stream;
        ASSERT_TRUE(stream.create(&tracker_, 4096, mode));
        const std::vector<uint8_t> data(40, 7);
        EXPECT_EQ(stream.push(data.data(), data.size(), 40), StreamBuffer::kNoSpace);
        EXPECT_EQ(stream.push(data.data(), data.size(), 512), StreamBuffer::kNoSpace);
        for (int i = 0; i < 200; ++i) {  // through several regions and wraps
            ASSERT_NE(stream.push(data.data(), data.size(), 4), StreamBuffer::kNoSpace);
            const size_t offset = stream.push(data.data(), 32, 32);
            ASSERT_NE(offset, StreamBuffer::kNoSpace);
            EXPECT_EQ(offset % 32, 0u) << i;
        }
    }
}

TEST_F(GlHelpersTest, StreamBufferReserveWritesInPlace) {
    StreamBuffer stream;
    ASSERT_TRUE(stream.create(&tracker_, 4096));
    size_t offset = 0;
    auto* target = static_cast<uint8_t*>(stream.reserve(8, 4, &offset));
    ASSERT_NE(target, nullptr);
    std::memcpy(target, "nprquake", 8);
    stream.unmap();
    glFinish();
    const auto bytes = read_buffer(stream.id(), offset, 8);
    EXPECT_EQ(std::string(bytes.begin(), bytes.end()), "nprquake");
}

}  // namespace
}  // namespace nq::npr::test
