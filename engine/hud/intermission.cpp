#include "hud/intermission.h"

#include <algorithm>
#include <cmath>

#include "hud/big_numbers.h"
#include "hud/scoreboard.h"

namespace nq {
namespace {

constexpr int kFieldDigits = 3;
constexpr float kNumbersX = 152;    // the left edge of each three-digit field
constexpr float kSeparatorX = 224;  // ':' or '/'
constexpr float kSecondNumberX = 240;
constexpr float kSecondsUnitsX = 264;
constexpr float kTimeY = 64;
constexpr float kSecretsY = 104;
constexpr float kMonstersY = 144;

void draw_completion_time(const HudCanvas& menu, double seconds_taken) {
    const HudPictureIds& ids = menu.pictures().ids();
    // Whole seconds; a demo's clock is untrusted, so keep it in range (NaN counts as 0).
    constexpr double kLongestShown = 1.0e9;
    double clamped = seconds_taken > 0 ? std::min(seconds_taken, kLongestShown) : 0.0;
    auto total = static_cast<int64_t>(clamped);
    int64_t minutes = total / 60;
    int64_t seconds = total % 60;
    draw_big_number(menu, kNumbersX, kTimeY, minutes, kFieldDigits, kWhiteNumbers);
    menu.picture(ids.colon, kSeparatorX, kTimeY);
    menu.picture(ids.numbers[kWhiteNumbers][seconds / 10], kSecondNumberX, kTimeY);
    menu.picture(ids.numbers[kWhiteNumbers][seconds % 10], kSecondsUnitsX, kTimeY);
}

void draw_fraction(const HudCanvas& menu, float y, int done, int total) {
    draw_big_number(menu, kNumbersX, y, done, kFieldDigits, kWhiteNumbers);
    menu.picture(menu.pictures().ids().slash, kSeparatorX, y);
    draw_big_number(menu, kSecondNumberX, y, total, kFieldDigits, kWhiteNumbers);
}

}  // namespace

void draw_intermission(const HudCanvas& menu, const ClientState& client) {
    if (client.level().game_type == kGameTypeDeathmatch) {
        draw_deathmatch_ranking(menu, client);
        return;
    }
    const HudPictureIds& ids = menu.pictures().ids();
    menu.picture(ids.complete, 64, 24);
    menu.picture(ids.inter, 0, 56);
    draw_completion_time(menu, client.completed_time());
    const PlayerState& player = client.player();
    draw_fraction(menu, kSecretsY, player.stats[kStatSecrets], player.stats[kStatTotalSecrets]);
    draw_fraction(menu, kMonstersY, player.stats[kStatMonsters], player.stats[kStatTotalMonsters]);
}

void draw_finale(const HudCanvas& menu) {
    PictureId finale = menu.pictures().ids().finale;
    menu.picture(finale, static_cast<float>((kVirtualWidth - menu.picture_width(finale)) / 2), 16);
}

}  // namespace nq
