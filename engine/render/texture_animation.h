// Animated brush textures, resolved from their names as Quake does at map load. A texture named
// "+<c><base>" belongs to the chain of <base>: c = '0'..'9' is the primary chain (frame 0..9),
// c = 'a'..'j' (either case) the alternate chain that brush entities show while their frame is
// not 0 (buttons that were pressed, for instance).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace nq {

inline constexpr int kMaxAnimationFrames = 10;

struct TextureAnimation {
    // The chain this texture belongs to, in frame order (texture indices); empty when the
    // texture is not animated. `alternate` is the other chain of the same base name: for a
    // "+0"-style texture the letter chain, for a "+a"-style texture the digit chain (frame != 0
    // swaps to it, whichever chain the surface starts with, as in Quake).
    std::vector<int32_t> frames;
    std::vector<int32_t> alternate;
};

struct TextureAnimations {
    std::vector<TextureAnimation> per_texture;  // parallel to the names given
    std::vector<std::string> warnings;
};

// Chains end at their first missing frame: "+0x", "+1x", "+3x" makes the chain {+0x, +1x} and
// "+3x" a still texture, with a warning (Quake refuses such maps). A repeated name keeps its
// first texture, with a warning.
TextureAnimations resolve_texture_animations(std::span<const std::string_view> names);

}  // namespace nq
