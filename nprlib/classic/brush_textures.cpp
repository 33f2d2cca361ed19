#include "classic/brush_textures.h"

#include <algorithm>
#include <atomic>
#include <span>
#include <thread>
#include <vector>

#include "abi/abi_access.h"
#include "gl/texture_upload.h"

namespace nq::npr::classic {
namespace {

// A grey/black checkerboard for textures the map did not carry.
BrushTextureGpu placeholder_texture(gl::ObjectTracker* tracker) {
    constexpr int kSize = 16;
    std::vector<uint8_t> rgba(kSize * kSize * 4);
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const uint8_t value = ((x / 8) ^ (y / 8)) ? 96 : 0;
            uint8_t* texel = &rgba[(y * kSize + x) * 4];
            texel[0] = texel[1] = texel[2] = value;
            texel[3] = 255;
        }
    }
    BrushTextureGpu texture;
    texture.base = gl::create_rgba8_texture(tracker, kSize, kSize, rgba, gl::kMipmappedRepeat);
    texture.size[0] = texture.size[1] = kSize;
    return texture;
}

// The w x h sub-image at column x0 of a palette image `stride` texels wide.
void copy_columns(const uint8_t* pixels, uint32_t stride, uint32_t x0, uint32_t width,
                  uint32_t height, std::vector<uint8_t>& out) {
    out.resize(static_cast<size_t>(width) * height);
    for (uint32_t y = 0; y < height; ++y) {
        for (uint32_t x = 0; x < width; ++x) out[y * width + x] = pixels[y * stride + x0 + x];
    }
}

void create_sky_layers(gl::ObjectTracker* tracker, const nqr_texture& source,
                       const uint8_t* palette, BrushTextureGpu& out) {
    const uint32_t half = source.width / 2;
    std::vector<uint8_t> layer, scratch;
    copy_columns(source.mips[0], source.width, half, half, source.height, layer);
    out.base =
        gl::create_palette_texture(tracker, static_cast<int>(half), static_cast<int>(source.height),
                                   layer, palette, {}, gl::kMipmappedRepeat, scratch);
    copy_columns(source.mips[0], source.width, 0, half, source.height, layer);
    out.sky_front = gl::create_palette_texture(
        tracker, static_cast<int>(half), static_cast<int>(source.height), layer, palette,
        {.transparent = gl::Transparent::index0}, gl::kMipmappedRepeat, scratch);
    out.size[0] = static_cast<float>(half);
    out.size[1] = static_cast<float>(source.height);
}

gl::PaletteExpansion expansion_of(SurfaceKind kind) {
    gl::PaletteExpansion expansion;
    expansion.blacken_fullbrights = kind != SurfaceKind::liquid;
    if (kind == SurfaceKind::fence) expansion.transparent = gl::Transparent::index255;
    return expansion;
}

bool has_pixels(const nqr_texture& source) {
    return source.mips[0] != nullptr && source.width > 0 && source.height > 0;
}

std::span<const uint8_t> base_pixels(const nqr_texture& source) {
    return {source.mips[0], static_cast<size_t>(source.width) * source.height};
}

// `filtered`: the base texels already expanded and filtered (may be null: done here).
BrushTextureGpu create_one(gl::ObjectTracker* tracker, const nqr_texture& source,
                           const uint8_t* palette, const gl::RgbaFilter* filter,
                           const std::vector<uint8_t>* filtered) {
    if (!has_pixels(source)) return placeholder_texture(tracker);
    BrushTextureGpu out;
    out.kind = surface_kind_of(source);
    if (out.kind == SurfaceKind::sky && source.width >= 2) {
        create_sky_layers(tracker, source, palette, out);
        return out;
    }
    const int width = static_cast<int>(source.width);
    const int height = static_cast<int>(source.height);
    const std::span<const uint8_t> pixels = base_pixels(source);
    std::vector<uint8_t> scratch;
    if (filtered && !filtered->empty()) {
        out.base =
            gl::create_rgba8_texture(tracker, width, height, *filtered, gl::kMipmappedRepeat);
    } else {
        out.base = gl::create_palette_texture(tracker, width, height, pixels, palette,
                                              expansion_of(out.kind), gl::kMipmappedRepeat, scratch,
                                              filter);
    }
    if (out.kind != SurfaceKind::liquid) {
        out.fullbright = gl::create_fullbright_texture(tracker, width, height, pixels, palette,
                                                       gl::kMipmappedRepeat, scratch);
    }
    out.size[0] = static_cast<float>(width);
    out.size[1] = static_cast<float>(height);
    return out;
}

// A filter costs milliseconds per texture (the illustrative style's abstraction), so the base
// texels of every filtered texture are expanded and filtered on worker threads before the
// uploads, which stay on the GL thread. An entry left empty (no pixels, sky, or a filter that
// threw) is done the ordinary way.
std::vector<std::vector<uint8_t>> filter_in_parallel(const nqr_brush_model& brush,
                                                     const uint8_t* palette,
                                                     const gl::RgbaFilter& filter) {
    std::vector<std::vector<uint8_t>> filtered(brush.num_textures);
    std::atomic<uint32_t> next{0};
    auto work = [&] {
        for (uint32_t i = next++; i < brush.num_textures; i = next++) {
            const nqr_texture& source = abi_element(brush.textures, i);
            const SurfaceKind kind = surface_kind_of(source);
            if (!has_pixels(source) || kind == SurfaceKind::sky) continue;
            try {
                gl::expand_palette_texels(int(source.width), int(source.height),
                                          base_pixels(source), palette, expansion_of(kind),
                                          filtered[i], &filter);
            } catch (...) {
                filtered[i].clear();
            }
        }
    };
    const unsigned workers =
        std::clamp(std::thread::hardware_concurrency(), 1u, std::min(8u, brush.num_textures));
    std::vector<std::thread> threads;
    for (unsigned w = 1; w < workers; ++w) threads.emplace_back(work);
    work();
    for (std::thread& thread : threads) thread.join();
    return filtered;
}

}  // namespace

SurfaceKind surface_kind_of(const nqr_texture& texture) {
    if (texture.flags & NQR_TEXTURE_SKY) return SurfaceKind::sky;
    if (texture.flags & NQR_TEXTURE_LIQUID) return SurfaceKind::liquid;
    if (texture.name != nullptr && texture.name[0] == '{') return SurfaceKind::fence;
    return SurfaceKind::lit;
}

std::vector<BrushTextureGpu> create_brush_textures(gl::ObjectTracker* tracker,
                                                   const nqr_brush_model& brush,
                                                   const uint8_t* palette_rgb,
                                                   const gl::RgbaFilter* filter) {
    std::vector<BrushTextureGpu> textures;
    textures.reserve(brush.num_textures + 1);
    std::vector<std::vector<uint8_t>> filtered;
    if (filter && *filter && brush.num_textures > 0) {
        filtered = filter_in_parallel(brush, palette_rgb, *filter);
    }
    for (uint32_t i = 0; i < brush.num_textures; ++i) {
        textures.push_back(create_one(tracker, abi_element(brush.textures, i), palette_rgb, filter,
                                      filtered.empty() ? nullptr : &filtered[i]));
    }
    textures.push_back(placeholder_texture(tracker));
    return textures;
}

}  // namespace nq::npr::classic
