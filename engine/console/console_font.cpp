#include "console/console_font.h"

#include "console/fallback_font_sheet.h"

namespace nq {
namespace {

constexpr int kCellPixels = kFontImageSize / kFontGlyphsPerRow;  // 8
constexpr size_t kFontPixelCount = static_cast<size_t>(kFontImageSize) * kFontImageSize;
constexpr Rgb kFallbackInk{235, 235, 225};
constexpr Rgb kFallbackAlternateInk{230, 170, 60};  // the gold half
// Inside an 8x8 cell the 5-pixel-wide drawings leave one column on the left, two on the right.
constexpr int kSheetColumnOffset = 1;

void put_pixel(RgbaImage& image, int x, int y, Rgb colour, uint8_t alpha) {
    size_t at = (static_cast<size_t>(y) * image.width + x) * 4;
    image.rgba[at + 0] = colour.r;
    image.rgba[at + 1] = colour.g;
    image.rgba[at + 2] = colour.b;
    image.rgba[at + 3] = alpha;
}

RgbaImage blank_font_image() {
    return RgbaImage{kFontImageSize, kFontImageSize, std::vector<uint8_t>(kFontPixelCount * 4, 0)};
}

// Draws glyph `index` of the sheet into font cell `cell` in `ink`.
void draw_sheet_glyph(RgbaImage& image, int index, int cell, Rgb ink) {
    std::span<const char* const> sheet = fallback_font_sheet();
    int block = index / kSheetGlyphsPerRow;
    int column = (index % kSheetGlyphsPerRow) * (kSheetGlyphWidth + 1);
    int cell_x = (cell % kFontGlyphsPerRow) * kCellPixels + kSheetColumnOffset;
    int cell_y = (cell / kFontGlyphsPerRow) * kCellPixels;
    for (int row = 0; row < kSheetGlyphHeight; ++row) {
        const char* pixels = sheet[static_cast<size_t>(block * kSheetGlyphHeight + row)];
        for (int x = 0; x < kSheetGlyphWidth; ++x) {
            if (pixels[column + x] == kSheetInk)
                put_pixel(image, cell_x + x, cell_y + row, ink, 255);
        }
    }
}

RgbaImage build_fallback_font() {
    RgbaImage image = blank_font_image();
    constexpr int kAlternateHalf = 128;
    for (int index = 0; index < kSheetGlyphCount; ++index) {
        int code = kSheetFirstChar + index;
        draw_sheet_glyph(image, index, code, kFallbackInk);
        draw_sheet_glyph(image, index, code + kAlternateHalf, kFallbackAlternateInk);
    }
    return image;
}

}  // namespace

Result<RgbaImage> conchars_to_rgba(std::span<const uint8_t> pixels, const Palette& palette) {
    if (pixels.size() != kFontPixelCount) {
        return Error{"conchars", 0,
                     "expected " + std::to_string(kFontPixelCount) + " pixels, got " +
                         std::to_string(pixels.size())};
    }
    return indexed_to_rgba(kFontImageSize, kFontImageSize, pixels, palette,
                           kConcharsTransparentIndex);
}

Result<RgbaImage> load_conchars_font(const Wad& gfx_wad, const Palette& palette) {
    const WadLump* lump = gfx_wad.find("conchars");
    if (!lump) return Error{gfx_wad.file_name, 0, "no \"conchars\" lump"};
    Result<Pic> pic = parse_wad_pic(gfx_wad, *lump);
    if (!pic) return pic.error();
    if (pic->width != kFontImageSize || pic->height != kFontImageSize) {
        return Error{gfx_wad.file_name, lump->file_offset,
                     "conchars is " + std::to_string(pic->width) + "x" +
                         std::to_string(pic->height) + ", expected 128x128"};
    }
    return conchars_to_rgba(pic->pixels, palette);
}

const RgbaImage& fallback_font() {
    static const RgbaImage font = build_fallback_font();
    return font;
}

}  // namespace nq
