// Screen-space quads for the 2D overlays (console, status bar, screen blends), built into a
// fixed CPU array: pictures (a whole texture or a region of an atlas), glyphs of a 16x16 font
// sheet, and solid rectangles. When the array is full it is handed to the flush callback
// (which uploads and draws it) and refilled, so memory stays fixed however much is on screen
// and nothing is allocated per frame.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string_view>
#include <vector>

namespace nq {

struct Colour {
    uint8_t r = 255, g = 255, b = 255, a = 255;
    friend bool operator==(const Colour&, const Colour&) = default;
};

// A 0..1 colour channel or opacity as a byte (rounded; clamped; NaN counts as 0).
uint8_t unit_to_byte(float value);

// How a quad takes its colour from the bound texture (QuadVertex::sampling).
enum QuadSampling : uint8_t {
    kSampleNone = 0,          // a solid colour
    kSampleFiltered = 128,    // the texture with its own filter (pictures)
    kSampleTexelExact = 255,  // the texel under the pixel, whatever the filter (glyphs)
};

// 24 bytes, the vertex layout of the quad shader: pixel position (y down), texture
// coordinates, colour, and how to sample the texture.
struct QuadVertex {
    float x, y;
    float u, v;
    uint8_t r, g, b, a;
    uint8_t sampling;  // QuadSampling
    uint8_t padding[3];
};
static_assert(sizeof(QuadVertex) == 24);

// A rectangle of the bound texture in texture coordinates (0..1, v down): one picture of an
// atlas, or the whole texture.
struct TextureRegion {
    float u0 = 0, v0 = 0, u1 = 1, v1 = 1;
    friend bool operator==(const TextureRegion&, const TextureRegion&) = default;
};

inline constexpr size_t kQuadBatchCapacity = 4096;  // quads per flush (16384 vertices)
inline constexpr size_t kVerticesPerQuad = 4;
inline constexpr size_t kIndicesPerQuad = 6;
inline constexpr int kFontSheetGlyphsPerRow = 16;  // 16x16 glyphs: glyph n at column n % 16

class QuadBatch {
  public:
    using FlushFn = std::function<void(std::span<const QuadVertex> vertices)>;

    explicit QuadBatch(size_t capacity_quads = kQuadBatchCapacity);

    // Called with the filled vertices (4 per quad: top-left, top-right, bottom-right,
    // bottom-left) whenever the batch is full and on flush().
    void set_flush(FlushFn flush) { flush_ = std::move(flush); }
    void flush();
    void clear() { quads_ = 0; }

    void solid(float x, float y, float width, float height, Colour colour);
    // `region` of the texture (default: all of it) stretched over the rectangle, sampled with
    // the texture's filter, its texels multiplied by `colour`.
    void image(float x, float y, float width, float height, Colour colour,
               TextureRegion region = {});
    // Glyph `index` (0..255) of the 16x16 font sheet that fills `font` (default: the whole
    // texture) as a `size`-pixel square at (x, y), texel-exact (never blurred into its
    // neighbours in the sheet).
    void glyph(uint8_t index, float x, float y, float size, Colour colour, TextureRegion font = {});
    // One glyph per byte, left to right from (x, y); spaces take room but no quad.
    void text(std::string_view bytes, float x, float y, float size, Colour colour,
              TextureRegion font = {});

    size_t quad_count() const { return quads_; }
    size_t capacity() const { return vertices_.size() / kVerticesPerQuad; }
    std::span<const QuadVertex> vertices() const {
        return std::span<const QuadVertex>(vertices_).first(quads_ * kVerticesPerQuad);
    }

  private:
    void add(float x0, float y0, float x1, float y1, TextureRegion uv, Colour colour,
             QuadSampling sampling);

    std::vector<QuadVertex> vertices_;  // sized once, never grows
    size_t quads_ = 0;
    FlushFn flush_;
};

}  // namespace nq
