#include "app/shell/game_data.h"

#include "app/frame/showroom.h"
#include "fs/vfs.h"

namespace nq {

namespace {

template <class T, class Parse>
std::optional<T> load(const Vfs& vfs, const char* path, Parse parse,
                      std::vector<std::string>& warnings) {
    auto bytes = vfs.read(path);
    if (!bytes) {
        warnings.push_back(std::string(path) + " not found: using a stand-in");
        return std::nullopt;
    }
    auto parsed = parse(bytes.value(), path);
    if (!parsed) {
        warnings.push_back(parsed.error().to_string());
        return std::nullopt;
    }
    for (const auto& w : parsed->warnings) warnings.push_back(std::string(path) + ": " + w);
    return std::move(parsed.value());
}

}  // namespace

GameData load_game_data(const Vfs* vfs) {
    GameData data;
    if (!vfs) return data;
    data.palette = load<Palette>(*vfs, "gfx/palette.lmp", parse_palette, data.warnings);
    data.colormap = load<Colormap>(*vfs, "gfx/colormap.lmp", parse_colormap, data.warnings);
    data.gfx_wad = load<Wad>(*vfs, "gfx.wad", parse_wad, data.warnings);
    return data;
}

std::array<uint8_t, 768> GameData::palette_bytes() const {
    if (!palette) return Showroom::builtin_palette();
    std::array<uint8_t, 768> out{};
    for (int i = 0; i < 256; ++i) {
        out[i * 3] = palette->colors[i].r;
        out[i * 3 + 1] = palette->colors[i].g;
        out[i * 3 + 2] = palette->colors[i].b;
    }
    return out;
}

}  // namespace nq
