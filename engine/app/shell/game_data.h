// The shared 2D and colour data of a game: palette, colormap and gfx.wad (console font).
// Everything is optional: a game without them still runs (the showroom palette and the
// built-in font stand in), with a warning naming what was missing.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "formats/palette.h"
#include "formats/wad.h"

namespace nq {

class Vfs;

struct GameData {
    std::optional<Palette> palette;
    std::optional<Colormap> colormap;
    std::optional<Wad> gfx_wad;
    std::vector<std::string> warnings;

    // 768 bytes: the game palette, or the showroom's built-in one.
    std::array<uint8_t, 768> palette_bytes() const;
};

GameData load_game_data(const Vfs* vfs);

}  // namespace nq
