#include "client/screen_flashes.h"

#include <algorithm>

namespace nq {
namespace {

constexpr int kMaxDamageByte = 255;
constexpr float kMinDamageCount = 10.0f;
constexpr float kDamageShiftPerCount = 3.0f;

// The colours Quake picks: pinker when the armour took most of the hit, pure red without any.
constexpr std::array<float, 3> kArmourMostlyColour{200, 100, 100};
constexpr std::array<float, 3> kSomeArmourColour{220, 50, 50};
constexpr std::array<float, 3> kBloodColour{255, 0, 0};
constexpr std::array<float, 3> kBonusColour{215, 186, 69};

// `shift` set at `since`, decayed by `per_second` until `now` (never below 0; a clock that went
// backwards decays nothing).
ColourShift decayed(const ColourShift& shift, double since, double now, float per_second) {
    double elapsed = std::max(0.0, now - since);
    ColourShift out = shift;
    out.percent = static_cast<float>(std::max(0.0, shift.percent - elapsed * per_second));
    return out;
}

}  // namespace

void ScreenFlashes::damage(int armor, int blood, double now) {
    armor = std::clamp(armor, 0, kMaxDamageByte);
    blood = std::clamp(blood, 0, kMaxDamageByte);
    float count = std::max(kMinDamageCount, 0.5f * static_cast<float>(blood + armor));
    pain_face_until_ = now + kPainFaceSeconds;

    ColourShift current = damage_shift(now);
    current.percent = std::min(kMaxDamageShift, current.percent + kDamageShiftPerCount * count);
    if (armor > blood) {
        current.colour = kArmourMostlyColour;
    } else if (armor > 0) {
        current.colour = kSomeArmourColour;
    } else {
        current.colour = kBloodColour;
    }
    damage_ = current;
    damage_time_ = now;
}

void ScreenFlashes::bonus(double now) {
    bonus_ = ColourShift{kBonusColour, kBonusShiftPercent};
    bonus_time_ = now;
}

ColourShift ScreenFlashes::damage_shift(double now) const {
    return decayed(damage_, damage_time_, now, kDamageShiftDecayPerSecond);
}

ColourShift ScreenFlashes::bonus_shift(double now) const {
    return decayed(bonus_, bonus_time_, now, kBonusShiftDecayPerSecond);
}

}  // namespace nq
