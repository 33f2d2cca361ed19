// k_d on the CPU: the surface colour the technical tones start from, read from an alias model's
// palette skin as the lit base texture holds it (fullbright pixels black, player colours
// translated, a holey model's transparent index left out):
//   - the skin's mean colour, from a histogram of its palette indices made once per skin image,
//     so that any player-colour translation averages in 256 steps;
//   - the texel under a vertex (its front-side skin coordinate), for texture_blend > 0.
// The face drawer takes the mean as a uniform and the edge drawer shades edge ends with it, so
// both start from the same k_d.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "classic/player_colors.h"
#include "nqr_renderer.h"

namespace nq::npr::technical {

using PaletteHistogram = std::array<uint32_t, 256>;

// One entity's skin, ready to give k_d.
struct SkinSample {
    glm::vec3 average{0.5f};
    const uint8_t* pixels = nullptr;  // palette indices, width x height; null: average only
    int width = 0, height = 0;
    const uint8_t* palette = nullptr;  // 768 bytes
    classic::Translation translation{};
    bool holey = false;

    // k_d at the vertex whose skin coordinate is (s, t): the average blended toward the
    // texel by `blend` (0..1).
    glm::vec3 kd(int32_t s, int32_t t, float blend) const;
};

// Per alias model: every skin image's index histogram.
class SkinTones {
  public:
    void build(const nqr_alias_model& model);
    // `pixels` is the image drawn (classic::AliasModelGpu::skin_pixels); an image this model
    // does not know is counted on the spot.
    SkinSample sample(const nqr_alias_model& model, const uint8_t* pixels, const nqr_entity& entity,
                      const uint8_t* palette) const;

  private:
    struct Image {
        const uint8_t* pixels;
        PaletteHistogram counts;
    };
    std::vector<Image> images_;
};

PaletteHistogram count_palette_indices(const nqr_alias_model& model, const uint8_t* pixels);

// The one-off form of SkinTones::sample, for drawers used without a registry.
SkinSample sample_skin(const nqr_alias_model& model, const uint8_t* pixels,
                       const nqr_entity& entity, const uint8_t* palette,
                       const PaletteHistogram* counts = nullptr);

}  // namespace nq::npr::technical
