// Shared by the hud_*_test.cpp files: LibreQuake's gfx.wad and palette, pictures decoded
// straight from the WAD (independently of the HUD's atlas), a client in a level with chosen
// stats, and the quads a HUD build emits.
#pragma once

#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

#include "client/client_state.h"
#include "common/file_io.h"
#include "draw2d/quad_batch.h"
#include "formats/lmp.h"
#include "formats/palette.h"
#include "formats/wad.h"
#include "hud/hud_pictures.h"
#include "hud/hud_scene.h"
#include "support/test_data.h"

namespace nq::test {

inline Wad lq1_gfx_wad() {
    auto bytes = read_file(lq1_dir() + "/gfx.wad");
    if (!bytes) throw std::runtime_error(bytes.error().to_string());
    auto wad = parse_wad(*bytes, "gfx.wad");
    if (!wad) throw std::runtime_error(wad.error().to_string());
    return std::move(*wad);
}

inline Palette lq1_palette() {
    auto bytes = read_file(lq1_dir() + "/gfx/palette.lmp");
    if (!bytes) throw std::runtime_error(bytes.error().to_string());
    auto palette = parse_palette(*bytes, "palette.lmp");
    if (!palette) throw std::runtime_error(palette.error().to_string());
    return std::move(*palette);
}

// A picture of gfx.wad as palette indices (255: transparent).
inline Pic wad_picture(const Wad& wad, const std::string& name) {
    const WadLump* lump = wad.find(name);
    if (!lump) throw std::runtime_error("no " + name + " in gfx.wad");
    auto pic = parse_wad_pic(wad, *lump);
    if (!pic) throw std::runtime_error(pic.error().to_string());
    return std::move(*pic);
}

struct HudTestData {
    Wad wad = lq1_gfx_wad();
    Palette palette = lq1_palette();
    HudPictures pictures = HudPictures::load(wad, palette, nullptr);
};

// A single-player client in a level, at client time `now`, with `health`, `armor`, `ammo`
// and `items`.
inline void enter_level(ClientState& client, double now = 10.0, int max_clients = 1,
                        int game_type = 0) {
    svc::ServerInfo info;
    info.protocol = protocol::kFitzQuake;
    info.max_clients = max_clients;
    info.game_type = game_type;
    info.level_name = "The Test Level";
    info.models = {"maps/test1.bsp"};
    auto problem = client.apply(info);
    ASSERT_FALSE(problem) << *problem;
    client.set_time(now);
}

inline svc::ClientData player_data(int health, int armor, int ammo, int32_t items,
                                   int active_weapon = kItemShotgun) {
    svc::ClientData d;
    d.health = health;
    d.armor = armor;
    d.ammo = ammo;
    d.items = items;
    d.active_weapon = active_weapon;
    d.shells = 25;
    return d;
}

// One emitted quad: its screen rectangle, texture region, colour and sampling.
struct EmittedQuad {
    float x0, y0, x1, y1;
    TextureRegion region;
    Colour colour;
    uint8_t sampling;
};

// The quads `build(batch)` emits, in order.
template <typename Build>
std::vector<EmittedQuad> emitted_quads(Build&& build) {
    std::vector<EmittedQuad> quads;
    QuadBatch batch(64);
    batch.set_flush([&](std::span<const QuadVertex> v) {
        for (size_t i = 0; i + 3 < v.size(); i += 4) {
            quads.push_back({v[i].x, v[i].y, v[i + 2].x, v[i + 2].y,
                             TextureRegion{v[i].u, v[i].v, v[i + 2].u, v[i + 2].v},
                             Colour{v[i].r, v[i].g, v[i].b, v[i].a}, v[i].sampling});
        }
    });
    build(batch);
    batch.flush();
    return quads;
}

inline std::vector<EmittedQuad> hud_quads(const ClientState& client, const HudFrame& frame,
                                          const HudPictures& pictures) {
    return emitted_quads([&](QuadBatch& batch) { build_hud(client, frame, pictures, batch); });
}

inline HudFrame hud_frame(int width, int height, float viewsize = 100, float scale = 1) {
    HudFrame frame;
    frame.screen = HudScreen{width, height, scale};
    frame.settings.viewsize = viewsize;
    return frame;
}

}  // namespace nq::test
