#include "render/surface_reflectivity.h"

namespace nq {

namespace {

constexpr uint8_t kFenceTransparentIndex = 255;

glm::vec3 average_colour(const BspTexture& texture, const PaletteBytes& palette) {
    const std::vector<uint8_t>& pixels = texture.mips[0].pixels;
    const bool fence = !texture.name.empty() && texture.name[0] == '{';
    glm::dvec3 sum(0.0);
    size_t counted = 0;
    for (uint8_t index : pixels) {
        if (fence && index == kFenceTransparentIndex) continue;
        sum += glm::dvec3(palette[index * 3], palette[index * 3 + 1], palette[index * 3 + 2]);
        ++counted;
    }
    if (counted == 0) return glm::vec3(kDefaultReflectivity);
    return glm::vec3(sum / (double(counted) * 255.0));
}

}  // namespace

std::vector<glm::vec3> texture_reflectivity(const Bsp& bsp,
                                            const std::optional<PaletteBytes>& palette) {
    std::vector<glm::vec3> out(bsp.textures.size(), glm::vec3(kDefaultReflectivity));
    if (!palette) return out;
    for (size_t i = 0; i < bsp.textures.size(); ++i) {
        if (!bsp.textures[i].placeholder) out[i] = average_colour(bsp.textures[i], *palette);
    }
    return out;
}

}  // namespace nq
