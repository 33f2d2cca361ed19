// Quake's stereo spatialization (SND_Spatialize): distance attenuation against the nominal
// clip distance and left/right separation from the listener's right vector.
#pragma once

#include <array>

namespace nq {

using SoundVec3 = std::array<float, 3>;

inline constexpr float kNominalClipDistance = 1000;  // Quake's sound_nominal_clip_dist

// Quake's attenuations (the byte on the wire is attenuation * 64).
inline constexpr float kAttenuationNone = 0;
inline constexpr float kAttenuationNormal = 1;
inline constexpr float kAttenuationIdle = 2;
inline constexpr float kAttenuationStatic = 3;

struct Listener {
    SoundVec3 origin{};
    SoundVec3 right{1, 0, 0};
    int view_entity = 0;  // its sounds are heard at full volume in both ears
};

struct StereoVolume {
    int left = 0, right = 0;  // 0..255 (more when master volume is above 255)
};

// dist = |origin - listener| * dist_mult; each side = master * (1 - dist) * (1 -/+ dot), where
// dot = right . direction to the source; truncated to an integer and never below 0.
StereoVolume spatialize(const SoundVec3& origin, float master_volume, float dist_mult,
                        const Listener& listener);

}  // namespace nq
