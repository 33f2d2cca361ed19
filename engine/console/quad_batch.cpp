#include "console/quad_batch.h"

#include <algorithm>

namespace nq {
namespace {

constexpr int kAtlasGlyphsPerRow = 16;
constexpr float kAtlasGlyphSpan = 1.0f / kAtlasGlyphsPerRow;

}  // namespace

QuadBatch::QuadBatch(size_t capacity_quads)
    : vertices_(std::max<size_t>(capacity_quads, 1) * kVerticesPerQuad) {}

void QuadBatch::flush() {
    if (quads_ > 0 && flush_) flush_(vertices());
    quads_ = 0;
}

void QuadBatch::add(float x0, float y0, float x1, float y1, float u0, float v0, float u1, float v1,
                    Colour colour, bool textured) {
    if (quads_ == capacity()) flush();
    uint8_t t = textured ? 255 : 0;
    QuadVertex* v = &vertices_[quads_ * kVerticesPerQuad];
    v[0] = {x0, y0, u0, v0, colour.r, colour.g, colour.b, colour.a, t, {}};
    v[1] = {x1, y0, u1, v0, colour.r, colour.g, colour.b, colour.a, t, {}};
    v[2] = {x1, y1, u1, v1, colour.r, colour.g, colour.b, colour.a, t, {}};
    v[3] = {x0, y1, u0, v1, colour.r, colour.g, colour.b, colour.a, t, {}};
    ++quads_;
}

void QuadBatch::solid(float x, float y, float width, float height, Colour colour) {
    add(x, y, x + width, y + height, 0, 0, 0, 0, colour, false);
}

void QuadBatch::glyph(uint8_t index, float x, float y, float size, Colour colour) {
    float u = static_cast<float>(index % kAtlasGlyphsPerRow) * kAtlasGlyphSpan;
    float v = static_cast<float>(index / kAtlasGlyphsPerRow) * kAtlasGlyphSpan;
    add(x, y, x + size, y + size, u, v, u + kAtlasGlyphSpan, v + kAtlasGlyphSpan, colour, true);
}

void QuadBatch::image(float x, float y, float width, float height, Colour colour) {
    add(x, y, x + width, y + height, 0, 0, 1, 1, colour, true);
}

void QuadBatch::text(std::string_view bytes, float x, float y, float size, Colour colour) {
    for (char c : bytes) {
        if (c != ' ') glyph(static_cast<uint8_t>(c), x, y, size, colour);
        x += size;
    }
}

}  // namespace nq
