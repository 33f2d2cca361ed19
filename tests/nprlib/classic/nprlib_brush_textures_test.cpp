// A style's brush-texture filter (classic/brush_textures.h) runs on worker threads before the
// uploads: every filtered kind (lit, fence, liquid) is filtered exactly once, sky and textures
// without pixels never, and each uploaded base texture holds exactly what the sequential
// expand-and-filter computes here.
#include <atomic>
#include <string>
#include <vector>

#include "classic/brush_textures.h"
#include "gl/palette_image.h"
#include "gl/texture_upload.h"
#include "support/nprlib_test_support.h"

namespace nq::npr::test {
namespace {

class BrushTexturesTest : public GlSuiteTest<BrushTexturesTest> {};

struct SourceTexture {
    std::string name;
    uint32_t width, height, flags;
    std::vector<uint8_t> pixels;
};

// Palette indices from a seed, with fence holes (255) and fullbrights (240+) among them.
std::vector<uint8_t> pattern(uint32_t width, uint32_t height, uint32_t seed) {
    std::vector<uint8_t> out(size_t(width) * height);
    for (size_t i = 0; i < out.size(); ++i)
        out[i] = uint8_t((i * 37 + seed * 11 + i / width) % 256);
    return out;
}

// Each channel inverted, the alpha kept: a filter whose result is easy to recompute.
void invert(int, int, std::vector<uint8_t>& rgba) {
    for (size_t i = 0; i < rgba.size(); ++i) {
        if (i % 4 != 3) rgba[i] = uint8_t(255 - rgba[i]);
    }
}

std::vector<uint8_t> read_back(GLuint texture, uint32_t width, uint32_t height) {
    std::vector<uint8_t> rgba(size_t(width) * height * 4);
    glBindTexture(GL_TEXTURE_2D, texture);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    return rgba;
}

TEST_F(BrushTexturesTest, TheFilterRunsOncePerFilteredTextureAndUploadsWhatItMade) {
    std::vector<SourceTexture> sources;
    for (uint32_t i = 0; i < 12; ++i) {
        const uint32_t width = 16u << (i % 3), height = 16u << ((i + 1) % 2);
        sources.push_back(
            {"wall" + std::to_string(i), width, height, 0, pattern(width, height, i)});
    }
    sources[3].name = "{fence";
    sources[5].name = "*water";
    sources[5].flags = NQR_TEXTURE_LIQUID;
    sources[7].name = "sky1";
    sources[7].flags = NQR_TEXTURE_SKY;
    sources[9].pixels.clear();  // a texture the map did not carry
    std::vector<nqr_texture> textures(sources.size());
    for (size_t i = 0; i < sources.size(); ++i) {
        nqr_texture& t = textures[i];
        t.size = sizeof(nqr_texture);
        t.name = sources[i].name.c_str();
        t.width = sources[i].width;
        t.height = sources[i].height;
        t.flags = sources[i].flags;
        t.mips[0] = sources[i].pixels.empty() ? nullptr : sources[i].pixels.data();
    }
    nqr_brush_model brush{};
    brush.size = sizeof(nqr_brush_model);
    brush.num_textures = uint32_t(textures.size());
    brush.textures = textures.data();

    const std::array<uint8_t, 768> palette = make_test_palette();
    std::atomic<int> calls{0};
    const gl::RgbaFilter filter = [&](int width, int height, std::vector<uint8_t>& rgba) {
        ++calls;
        EXPECT_EQ(rgba.size(), size_t(width) * size_t(height) * 4);
        invert(width, height, rgba);
    };
    gl::ObjectTracker tracker;
    {
        std::vector<classic::BrushTextureGpu> gpu =
            classic::create_brush_textures(&tracker, brush, palette.data(), &filter);
        ASSERT_EQ(gpu.size(), textures.size() + 1);  // and the placeholder
        EXPECT_EQ(calls.load(), 10);                 // all but the sky and the missing one
        for (size_t i = 0; i < sources.size(); ++i) {
            const classic::SurfaceKind kind = classic::surface_kind_of(textures[i]);
            if (kind == classic::SurfaceKind::sky || sources[i].pixels.empty()) continue;
            gl::PaletteExpansion expansion;
            expansion.blacken_fullbrights = kind != classic::SurfaceKind::liquid;
            if (kind == classic::SurfaceKind::fence)
                expansion.transparent = gl::Transparent::index255;
            std::vector<uint8_t> expected;
            const gl::RgbaFilter sequential = invert;
            gl::expand_palette_texels(int(sources[i].width), int(sources[i].height),
                                      sources[i].pixels, palette.data(), expansion, expected,
                                      &sequential);
            EXPECT_EQ(read_back(gpu[i].base.id(), sources[i].width, sources[i].height), expected)
                << sources[i].name;
        }
        EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    }
    EXPECT_EQ(tracker.total_live(), 0);
}

}  // namespace
}  // namespace nq::npr::test
