// What the server's damage and pickup events leave on screen for a moment, as Quake's client
// keeps them: the red damage flash (svc_damage), the gold bonus flash (the "bf" command a
// server stuffs on an item pickup) and the status bar face's pain frame.
//
// Both flashes are Quake colour shifts (cshift): a colour and a "percent" (really an alpha
// out of 255) that decays linearly over client time -- 150 per second for damage, 100 for the
// bonus. Each is a function of the time asked about, so a paused demo holds its flash and a
// timedemo decays it by demo time.
#pragma once

#include <array>

namespace nq {

// A tint over the whole view: `colour` (0..255 per channel) at `percent` / 255 opacity.
struct ColourShift {
    std::array<float, 3> colour{};
    float percent = 0;
    friend bool operator==(const ColourShift&, const ColourShift&) = default;
};

inline constexpr float kDamageShiftDecayPerSecond = 150.0f;
inline constexpr float kBonusShiftDecayPerSecond = 100.0f;
inline constexpr float kMaxDamageShift = 150.0f;
inline constexpr float kBonusShiftPercent = 50.0f;
inline constexpr double kPainFaceSeconds = 0.2;

class ScreenFlashes {
  public:
    // svc_damage at client time `now`: `armor` and `blood` are the points the armour and the
    // health took (bytes on the wire; anything else is clamped to 0..255).
    void damage(int armor, int blood, double now);
    // The bonus flash at `now` (it restarts at full strength).
    void bonus(double now);
    void clear() { *this = {}; }

    ColourShift damage_shift(double now) const;
    ColourShift bonus_shift(double now) const;
    // Whether the status bar shows the pain face at `now` (0.2 s after each hit).
    bool pain_face(double now) const { return now <= pain_face_until_; }

  private:
    ColourShift damage_;  // as of damage_time_
    double damage_time_ = 0;
    ColourShift bonus_;  // as of bonus_time_
    double bonus_time_ = 0;
    double pain_face_until_ = -1;
};

}  // namespace nq
