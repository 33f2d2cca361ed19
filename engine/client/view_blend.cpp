#include "client/view_blend.h"

#include <algorithm>
#include <array>

#include "client/view.h"

namespace nq {
namespace {

constexpr float kPercentScale = 255.0f;  // a shift's percent is an alpha out of 255

constexpr ColourShift kNoShift{};
constexpr ColourShift kWaterShift{{130, 80, 50}, 128};
constexpr ColourShift kSlimeShift{{0, 25, 5}, 150};
constexpr ColourShift kLavaShift{{255, 80, 0}, 150};

constexpr ColourShift kQuadShift{{0, 0, 255}, 30};
constexpr ColourShift kSuitShift{{0, 255, 0}, 20};
constexpr ColourShift kInvisibilityShift{{100, 100, 100}, 100};
constexpr ColourShift kInvulnerabilityShift{{255, 255, 0}, 30};

}  // namespace

ColourShift contents_shift(int contents) {
    switch (contents) {
        case kContentsWater:
            return kWaterShift;
        case kContentsSlime:
            return kSlimeShift;
        case kContentsLava:
            return kLavaShift;
        default:  // empty, solid, sky, or unknown
            return kNoShift;
    }
}

ColourShift powerup_shift(int32_t items) {
    if (items & kItemQuad) return kQuadShift;
    if (items & kItemSuit) return kSuitShift;
    if (items & kItemInvisibility) return kInvisibilityShift;
    if (items & kItemInvulnerability) return kInvulnerabilityShift;
    return kNoShift;
}

ScreenBlend mix_colour_shifts(std::span<const ColourShift> shifts) {
    float r = 0, g = 0, b = 0, a = 0;
    for (const ColourShift& shift : shifts) {
        float opacity = shift.percent / kPercentScale;
        if (!(opacity > 0)) continue;  // also skips NaN
        a += opacity * (1 - a);
        // The new shift's share of what is there now.
        float share = opacity / a;
        r = r * (1 - share) + shift.colour[0] * share;
        g = g * (1 - share) + shift.colour[1] * share;
        b = b * (1 - share) + shift.colour[2] * share;
    }
    return ScreenBlend{r / kPercentScale, g / kPercentScale, b / kPercentScale,
                       std::clamp(a, 0.0f, 1.0f)};
}

ScreenBlend view_blend(const ClientState& client, int eye_contents) {
    double now = client.time();
    const ScreenFlashes& flashes = client.flashes();
    if (client.intermission() != Intermission::None) {
        std::array<ColourShift, 1> contents{contents_shift(eye_contents)};
        return mix_colour_shifts(contents);
    }
    std::array<ColourShift, 4> shifts{contents_shift(eye_contents), flashes.damage_shift(now),
                                      flashes.bonus_shift(now),
                                      powerup_shift(client.player().items)};
    return mix_colour_shifts(shifts);
}

}  // namespace nq
