// The map's light entities, as needed to pick the direction light comes from at a point.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "formats/entities.h"

namespace nq {

inline constexpr float kDefaultLightBrightness = 300.0f;  // light tools' default "light" value

// Light tools' falloff ("delay" key): 0 linear (the light reaches brightness / wait units);
// the others (1/x, 1/x^2, none, ...) reach far, so only the culling range bounds them.
enum class LightFalloff { linear, far_reaching };

struct LightEntity {
    glm::vec3 origin{0.0f};
    float brightness = kDefaultLightBrightness;  // "light" (or "_light")
    glm::vec3 color{1.0f};                       // "_color", scaled so its largest component is 1
    uint32_t style = 0;  // "style": switchable and flickering lights follow lightstyles
    float wait = 1.0f;   // "wait": distance scale of the linear falloff
    LightFalloff falloff = LightFalloff::linear;
    // "delay" as the light tools read it: 0 linear, 1 inverse distance, 2 inverse square,
    // 3 infinite, 4 local minimum (infinite here), 5 inverse square from 128 units; other
    // values count as 0.
    int delay = 0;

    // How far the light reaches (linear: brightness / wait).
    float reach() const;
};

// Every entity whose classname starts with "light" and that has a valid origin ("light",
// "light_fluoro", "light_torch_small_walltorch", ...). Odd values (unparseable numbers, a
// negative brightness, a style beyond 63) are replaced by defaults with a warning.
std::vector<LightEntity> find_light_entities(const EntityList& entities,
                                             std::vector<std::string>& warnings);

}  // namespace nq
