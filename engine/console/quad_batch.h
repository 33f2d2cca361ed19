// Screen-space quads for the console, built into a fixed CPU array: glyphs of the 16x16 font
// atlas and solid rectangles. When the array is full it is handed to the flush callback (which
// uploads and draws it) and refilled, so memory stays fixed however much text is on screen and
// nothing is allocated per frame.
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
};

// 24 bytes, the vertex layout of the console shader: pixel position (y down), atlas
// coordinates, colour, and whether to sample the texture (0: solid colour).
struct QuadVertex {
    float x, y;
    float u, v;
    uint8_t r, g, b, a;
    uint8_t textured;
    uint8_t padding[3];
};
static_assert(sizeof(QuadVertex) == 24);

inline constexpr size_t kQuadBatchCapacity = 4096;  // quads per flush (16384 vertices)
inline constexpr size_t kVerticesPerQuad = 4;
inline constexpr size_t kIndicesPerQuad = 6;

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
    // Glyph `index` (0..255) of the 16x16 atlas as a `size`-pixel square at (x, y).
    void glyph(uint8_t index, float x, float y, float size, Colour colour);
    // A whole texture stretched over the rectangle.
    void image(float x, float y, float width, float height, Colour colour);
    // One glyph per byte, left to right from (x, y); spaces take room but no quad.
    void text(std::string_view bytes, float x, float y, float size, Colour colour);

    size_t quad_count() const { return quads_; }
    size_t capacity() const { return vertices_.size() / kVerticesPerQuad; }
    std::span<const QuadVertex> vertices() const {
        return std::span<const QuadVertex>(vertices_).first(quads_ * kVerticesPerQuad);
    }

  private:
    void add(float x0, float y0, float x1, float y1, float u0, float v0, float u1, float v1,
             Colour colour, bool textured);

    std::vector<QuadVertex> vertices_;  // sized once, never grows
    size_t quads_ = 0;
    FlushFn flush_;
};

}  // namespace nq
