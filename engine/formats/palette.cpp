#include "formats/palette.h"

#include <algorithm>

#include "common/byte_reader.h"

namespace nq {

namespace {

std::string trailing_warning(size_t extra, size_t expected, const char* what) {
    return std::to_string(extra) + " trailing byte(s) after the " + std::to_string(expected) +
           "-byte " + what + " (ignored)";
}

}  // namespace

Result<Palette> parse_palette(std::span<const uint8_t> data, const std::string& name) {
    return capture_errors(name, [&] {
        ByteReader in(data, name);
        if (in.size() < kPaletteBytes) {
            in.fail("palette needs " + std::to_string(kPaletteBytes) +
                    " bytes (256 RGB triples), " + "file has " + std::to_string(in.size()));
        }
        Palette pal;
        for (Rgb& c : pal.colors) {
            c.r = in.u8();
            c.g = in.u8();
            c.b = in.u8();
        }
        if (!in.at_end()) {
            pal.warnings.push_back(trailing_warning(in.remaining(), kPaletteBytes, "palette"));
        }
        return pal;
    });
}

Result<Colormap> parse_colormap(std::span<const uint8_t> data, const std::string& name) {
    return capture_errors(name, [&] {
        ByteReader in(data, name);
        if (in.size() < kColormapBytes) {
            in.fail("colormap needs " + std::to_string(kColormapBytes) + " bytes (64 light " +
                    "levels x 256), file has " + std::to_string(in.size()));
        }
        Colormap map;
        auto rows = in.bytes(kColormapBytes);
        map.table.assign(rows.begin(), rows.end());
        // id's colormap.lmp ends with one extra byte; harmless either way.
        if (!in.at_end()) {
            map.warnings.push_back(trailing_warning(in.remaining(), kColormapBytes, "colormap"));
        }
        return map;
    });
}

namespace {

void copy_ramp(std::array<uint8_t, kPaletteColors>& table, int range_start, int color) {
    const int row_start = std::clamp(color, 0, kPlayerColorRows - 1) * kColorRampSize;
    const bool light_to_dark = row_start >= 8 * kColorRampSize;
    for (int i = 0; i < kColorRampSize; ++i) {
        int source = light_to_dark ? row_start + kColorRampSize - 1 - i : row_start + i;
        table[range_start + i] = static_cast<uint8_t>(source);
    }
}

}  // namespace

std::array<uint8_t, kPaletteColors> player_translation(int shirt, int pants) {
    std::array<uint8_t, kPaletteColors> table{};
    for (int i = 0; i < kPaletteColors; ++i) table[i] = static_cast<uint8_t>(i);
    copy_ramp(table, kShirtRangeStart, shirt);
    copy_ramp(table, kPantsRangeStart, pants);
    return table;
}

}  // namespace nq
