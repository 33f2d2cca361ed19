#include "draw2d/quad_batch.h"

#include <algorithm>
#include <cmath>

namespace nq {

uint8_t unit_to_byte(float value) {
    if (!(value > 0)) return 0;  // also NaN
    return static_cast<uint8_t>(std::lround(std::min(value, 1.0f) * 255.0f));
}

QuadBatch::QuadBatch(size_t capacity_quads)
    : vertices_(std::max<size_t>(capacity_quads, 1) * kVerticesPerQuad) {}

void QuadBatch::flush() {
    if (quads_ > 0 && flush_) flush_(vertices());
    quads_ = 0;
}

void QuadBatch::add(float x0, float y0, float x1, float y1, TextureRegion uv, Colour colour,
                    QuadSampling sampling) {
    if (quads_ == capacity()) flush();
    uint8_t t = sampling;
    QuadVertex* v = &vertices_[quads_ * kVerticesPerQuad];
    v[0] = {x0, y0, uv.u0, uv.v0, colour.r, colour.g, colour.b, colour.a, t, {}};
    v[1] = {x1, y0, uv.u1, uv.v0, colour.r, colour.g, colour.b, colour.a, t, {}};
    v[2] = {x1, y1, uv.u1, uv.v1, colour.r, colour.g, colour.b, colour.a, t, {}};
    v[3] = {x0, y1, uv.u0, uv.v1, colour.r, colour.g, colour.b, colour.a, t, {}};
    ++quads_;
}

void QuadBatch::solid(float x, float y, float width, float height, Colour colour) {
    add(x, y, x + width, y + height, TextureRegion{0, 0, 0, 0}, colour, kSampleNone);
}

void QuadBatch::image(float x, float y, float width, float height, Colour colour,
                      TextureRegion region) {
    add(x, y, x + width, y + height, region, colour, kSampleFiltered);
}

void QuadBatch::glyph(uint8_t index, float x, float y, float size, Colour colour,
                      TextureRegion font) {
    float span_u = (font.u1 - font.u0) / kFontSheetGlyphsPerRow;
    float span_v = (font.v1 - font.v0) / kFontSheetGlyphsPerRow;
    float u = font.u0 + static_cast<float>(index % kFontSheetGlyphsPerRow) * span_u;
    float v = font.v0 + static_cast<float>(index / kFontSheetGlyphsPerRow) * span_v;
    add(x, y, x + size, y + size, TextureRegion{u, v, u + span_u, v + span_v}, colour,
        kSampleTexelExact);
}

void QuadBatch::text(std::string_view bytes, float x, float y, float size, Colour colour,
                     TextureRegion font) {
    for (char c : bytes) {
        if (c != ' ') glyph(static_cast<uint8_t>(c), x, y, size, colour, font);
        x += size;
    }
}

}  // namespace nq
