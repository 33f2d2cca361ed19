#include "hud/scoreboard.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string_view>

namespace nq {
namespace {

constexpr uint8_t kLeftBracket = 16;  // conchars: the brackets around the viewer's frags
constexpr uint8_t kRightBracket = 17;
constexpr uint8_t kViewerMarker = 12;  // the ranking's arrow at the viewer's line
constexpr uint8_t kAlternateColours = 128;
constexpr size_t kInventoryFragPlayers = 4;
constexpr size_t kLongLevelName = 40;  // characters; longer names scroll across the bar
constexpr double kScrollPixelsPerSecond = 30;
constexpr int kMiniOverlayMinWidth = 512;

// Palette indices of a player's shirt and pants colours (the middle of each colour's ramp).
uint8_t shirt_colour(int colors) {
    return static_cast<uint8_t>((colors & 0xf0) + 8);
}
uint8_t pants_colour(int colors) {
    return static_cast<uint8_t>(((colors & 0x0f) << 4) + 8);
}

// "%3i" of the frags, always three characters (longer values keep their first three).
std::array<char, 3> frag_text(int frags) {
    std::array<char, 16> text{};
    std::snprintf(text.data(), text.size(), "%3d", frags);
    return {text[0], text[1], text[2]};
}

void draw_frag_characters(const HudCanvas& canvas, float x, float y, int frags) {
    std::array<char, 3> text = frag_text(frags);
    for (size_t i = 0; i < text.size(); ++i) {
        canvas.character(x + static_cast<float>(i) * kCharacterSize, y,
                         static_cast<uint8_t>(text[i]));
    }
}

bool is_viewer(const ClientState& client, int slot) {
    return slot == client.view_entity() - 1;
}

// The map's file name without directory and extension ("maps/e1m1.bsp" -> "e1m1").
std::string_view map_name(const ClientState& client) {
    auto names = client.model_names();
    if (names.size() < 2) return {};
    std::string_view name = names[1];
    size_t slash = name.find_last_of('/');
    if (slash != std::string_view::npos) name.remove_prefix(slash + 1);
    return name.substr(0, name.find_last_of('.'));
}

// `text` from (x, y) on, drawing only the characters that lie wholly inside [left, right).
void draw_clipped_text(const HudCanvas& canvas, float x, float y, std::string_view text, float left,
                       float right) {
    for (char c : text) {
        if (x >= left && x + kCharacterSize <= right) {
            canvas.character(x, y, static_cast<uint8_t>(c));
        }
        x += kCharacterSize;
    }
}

// The level's title line: centred, or scrolling in a loop with "///" between the copies.
void draw_level_title(const HudCanvas& canvas, std::string_view title, float y, double real_time) {
    auto length = static_cast<float>(title.size());
    if (title.size() <= kLongLevelName) {
        canvas.text(kVirtualWidth / 2.0f - length * kCharacterSize / 2, y, title);
        return;
    }
    float loop = length * kCharacterSize + 5 * kCharacterSize;
    // Whole pixels of scroll, within one loop (fmod: any clock value stays in range).
    double scrolled = std::fmod(std::max(0.0, real_time) * kScrollPixelsPerSecond, loop);
    float x = -std::floor(static_cast<float>(std::isfinite(scrolled) ? scrolled : 0.0));
    draw_clipped_text(canvas, x, y, title, 0, kVirtualWidth);
    draw_clipped_text(canvas, x + loop - 4 * kCharacterSize, y, "///", 0, kVirtualWidth);
    draw_clipped_text(canvas, x + loop, y, title, 0, kVirtualWidth);
}

}  // namespace

FragOrder sort_frags(const ClientState& client) {
    FragOrder order;
    std::span<const ScoreboardEntry> scores = client.scoreboard();
    for (size_t slot = 0; slot < scores.size() && order.count < order.clients.size(); ++slot) {
        if (!scores[slot].name.empty()) order.clients[order.count++] = static_cast<int>(slot);
    }
    std::stable_sort(order.clients.begin(), order.clients.begin() + order.count, [&](int a, int b) {
        return scores[static_cast<size_t>(a)].frags > scores[static_cast<size_t>(b)].frags;
    });
    return order;
}

void draw_solo_scoreboard(const HudCanvas& status_bar, const ClientState& client,
                          double real_time) {
    const PlayerState& player = client.player();
    std::array<char, 64> line{};
    std::snprintf(line.data(), line.size(), "Kills: %d/%d", player.stats[kStatMonsters],
                  player.stats[kStatTotalMonsters]);
    status_bar.text(8, kStatusBarTop + 12, line.data());
    int length = std::snprintf(line.data(), line.size(), "Secrets: %d/%d",
                               player.stats[kStatSecrets], player.stats[kStatTotalSecrets]);
    status_bar.text(static_cast<float>(312 - std::max(length, 0) * kCharacterSize),
                    kStatusBarTop + 12, line.data());

    std::array<char, 160> title{};
    std::string_view map = map_name(client);
    int title_length =
        std::snprintf(title.data(), title.size(), "%s (%.*s)", client.level().level_name.c_str(),
                      static_cast<int>(map.size()), map.data());
    size_t shown = std::min(static_cast<size_t>(std::max(title_length, 0)), title.size() - 1);
    draw_level_title(status_bar, std::string_view(title.data(), shown), kStatusBarTop + 4,
                     real_time);
}

void draw_inventory_frags(const HudCanvas& status_bar, const ClientState& client) {
    FragOrder order = sort_frags(client);
    std::span<const ScoreboardEntry> scores = client.scoreboard();
    float x = 184;
    for (size_t i = 0; i < std::min(order.count, kInventoryFragPlayers); ++i, x += 32) {
        int slot = order.clients[i];
        const ScoreboardEntry& s = scores[static_cast<size_t>(slot)];
        status_bar.fill(x + 10, 1, 28, 4, shirt_colour(s.colors));
        status_bar.fill(x + 10, 5, 28, 3, pants_colour(s.colors));
        draw_frag_characters(status_bar, x + 12, 0, s.frags);
        if (is_viewer(client, slot)) {
            status_bar.character(x + 6, 0, kLeftBracket);
            status_bar.character(x + 32, 0, kRightBracket);
        }
    }
}

void draw_mini_deathmatch_overlay(const HudCanvas& status_bar, const ClientState& client,
                                  float viewsize, int screen_width) {
    if (viewsize >= kViewsizeNoBars) return;
    if (static_cast<float>(screen_width) / status_bar.scale() < kMiniOverlayMinWidth) return;
    FragOrder order = sort_frags(client);
    std::span<const ScoreboardEntry> scores = client.scoreboard();
    bool short_bar = viewsize >= kViewsizeNoInventory;  // fewer lines, lower down
    int lines = short_bar ? 3 : 6;

    // Start so that the viewer is in the middle of the lines shown.
    int first = 0;
    for (size_t i = 0; i < order.count; ++i) {
        if (is_viewer(client, order.clients[i])) first = static_cast<int>(i) - lines / 2;
    }
    first = std::max(0, std::min(first, static_cast<int>(order.count) - lines));

    constexpr float x = kVirtualWidth + 4;
    for (float y = short_bar ? kStatusBarTop : 0;
         first < static_cast<int>(order.count) && y + kCharacterSize <= kStatusBarCanvasHeight;
         ++first, y += kCharacterSize) {
        int slot = order.clients[static_cast<size_t>(first)];
        const ScoreboardEntry& s = scores[static_cast<size_t>(slot)];
        status_bar.fill(x, y + 1, 40, 4, shirt_colour(s.colors));
        status_bar.fill(x, y + 5, 40, 3, pants_colour(s.colors));
        draw_frag_characters(status_bar, x + 8, y, s.frags);
        if (is_viewer(client, slot)) {
            status_bar.character(x, y, kLeftBracket);
            status_bar.character(x + 32, y, kRightBracket);
        }
        status_bar.text(x + 48, y, s.name);
    }
}

void draw_deathmatch_ranking(const HudCanvas& menu, const ClientState& client) {
    PictureId ranking = menu.pictures().ids().ranking;
    menu.picture(ranking, static_cast<float>((kVirtualWidth - menu.picture_width(ranking)) / 2), 8);
    FragOrder order = sort_frags(client);
    std::span<const ScoreboardEntry> scores = client.scoreboard();
    constexpr float x = 80;
    float y = 40;
    for (size_t i = 0; i < order.count; ++i, y += 10) {
        int slot = order.clients[i];
        const ScoreboardEntry& s = scores[static_cast<size_t>(slot)];
        menu.fill(x, y, 40, 4, shirt_colour(s.colors));
        menu.fill(x, y + 4, 40, 4, pants_colour(s.colors));
        draw_frag_characters(menu, x + 8, y, s.frags);
        if (is_viewer(client, slot)) menu.character(x - 8, y, kViewerMarker);
        // Names in the alternate (brown) half of the font, as Quake's menus print.
        float name_x = x + 64;
        for (char c : s.name) {
            menu.character(name_x, y,
                           static_cast<uint8_t>(static_cast<uint8_t>(c) + kAlternateColours));
            name_x += kCharacterSize;
        }
    }
}

}  // namespace nq
