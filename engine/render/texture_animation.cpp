#include "render/texture_animation.h"

#include <array>
#include <map>

namespace nq {

namespace {

enum class ChainKind { primary, alternate };

// Where an animated name belongs: its chain kind and frame number; false for still textures.
bool parse_frame_name(std::string_view name, ChainKind& kind, int& frame) {
    if (name.size() < 3 || name[0] != '+') return false;
    const char c = name[1];
    if (c >= '0' && c <= '9') {
        kind = ChainKind::primary;
        frame = c - '0';
        return true;
    }
    const char lower = (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
    if (lower >= 'a' && lower < 'a' + kMaxAnimationFrames) {
        kind = ChainKind::alternate;
        frame = lower - 'a';
        return true;
    }
    return false;
}

// The frames of one base name, by chain kind and frame number (-1 = not present).
struct ChainSlots {
    std::array<std::array<int32_t, kMaxAnimationFrames>, 2> slots;
    ChainSlots() {
        for (auto& chain : slots) chain.fill(-1);
    }
};

// The leading run of present frames; reports frames after a gap.
std::vector<int32_t> contiguous_frames(const std::array<int32_t, kMaxAnimationFrames>& slots,
                                       std::string_view base, char first_char,
                                       std::vector<std::string>& warnings) {
    std::vector<int32_t> chain;
    int gap = -1;
    for (int i = 0; i < kMaxAnimationFrames; ++i) {
        if (slots[i] < 0) {
            if (gap < 0) gap = i;
            continue;
        }
        if (gap < 0) {
            chain.push_back(slots[i]);
        } else {
            warnings.push_back("animated texture +" + std::string(1, char(first_char + i)) +
                               std::string(base) + " follows missing frame +" +
                               std::string(1, char(first_char + gap)) + std::string(base) +
                               ": the chain stops before the gap");
        }
    }
    return chain;
}

}  // namespace

TextureAnimations resolve_texture_animations(std::span<const std::string_view> names) {
    TextureAnimations out;
    out.per_texture.resize(names.size());
    std::map<std::string_view, ChainSlots> bases;  // ordered: warnings come out deterministic
    for (size_t i = 0; i < names.size(); ++i) {
        ChainKind kind;
        int frame = 0;
        if (!parse_frame_name(names[i], kind, frame)) continue;
        int32_t& slot = bases[names[i].substr(2)].slots[static_cast<int>(kind)][frame];
        if (slot >= 0) {
            out.warnings.push_back("texture " + std::string(names[i]) + " appears twice; " +
                                   "animating with the first one");
            continue;
        }
        slot = static_cast<int32_t>(i);
    }
    for (const auto& [base, chains] : bases) {
        const std::vector<int32_t> primary =
            contiguous_frames(chains.slots[0], base, '0', out.warnings);
        const std::vector<int32_t> alternate =
            contiguous_frames(chains.slots[1], base, 'a', out.warnings);
        for (int32_t t : primary) out.per_texture[t] = {primary, alternate};
        for (int32_t t : alternate) out.per_texture[t] = {alternate, primary};
    }
    return out;
}

}  // namespace nq
