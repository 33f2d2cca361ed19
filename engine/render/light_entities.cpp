#include "render/light_entities.h"

#include <algorithm>
#include <charconv>
#include <limits>
#include <optional>

namespace nq {

namespace {

constexpr uint32_t kMaxLightStyle = 63;
constexpr float kMaxLightDelay = 5;

std::optional<float> parse_number(std::string_view text) {
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
    float value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end == text.data()) return std::nullopt;
    return value;
}

// The value of `key` as a number; `fallback` when absent, `fallback` and a warning when bad.
float number_or(const Entity& e, std::string_view key, float fallback,
                std::vector<std::string>& warnings) {
    const auto text = find_value(e, key);
    if (!text) return fallback;
    const auto value = parse_number(*text);
    if (!value) {
        warnings.push_back("light at offset " + std::to_string(e.offset) + ": \"" +
                           std::string(key) + "\" is not a number (\"" + std::string(*text) +
                           "\"); using " + std::to_string(fallback));
        return fallback;
    }
    return *value;
}

// "_color" is written either as 0..1 or as 0..255 fractions; only the hue matters here.
glm::vec3 light_color(const Entity& e) {
    const auto c = find_vec3(e, "_color");
    if (!c) return glm::vec3(1.0f);
    const glm::vec3 v(std::max((*c)[0], 0.0f), std::max((*c)[1], 0.0f), std::max((*c)[2], 0.0f));
    const float peak = std::max({v.x, v.y, v.z});
    return peak > 0.0f ? v / peak : glm::vec3(1.0f);
}

LightEntity light_from(const Entity& e, const std::array<float, 3>& origin,
                       std::vector<std::string>& warnings) {
    LightEntity light;
    light.origin = {origin[0], origin[1], origin[2]};
    const bool has_light = find_value(e, "light").has_value();
    light.brightness =
        number_or(e, has_light ? "light" : "_light", kDefaultLightBrightness, warnings);
    if (light.brightness < 0) {
        // Negative lights darken; they never give a direction to light from.
        light.brightness = 0;
    }
    const float style = number_or(e, "style", 0, warnings);
    if (style >= 0 && style <= kMaxLightStyle) {
        light.style = static_cast<uint32_t>(style);
    } else {
        warnings.push_back("light at offset " + std::to_string(e.offset) + ": style " +
                           std::to_string(style) + " out of range; using 0");
    }
    light.wait = number_or(e, "wait", 1.0f, warnings);
    if (!(light.wait > 0)) light.wait = 1.0f;
    const float delay = number_or(e, "delay", 0, warnings);
    light.falloff = delay == 0 ? LightFalloff::linear : LightFalloff::far_reaching;
    light.delay = delay >= 0 && delay <= kMaxLightDelay ? int(delay) : 0;
    light.color = light_color(e);
    return light;
}

}  // namespace

float LightEntity::reach() const {
    return falloff == LightFalloff::linear ? brightness / wait
                                           : std::numeric_limits<float>::infinity();
}

std::vector<LightEntity> find_light_entities(const EntityList& entities,
                                             std::vector<std::string>& warnings) {
    std::vector<LightEntity> lights;
    for (const Entity& e : entities.entities) {
        if (classname(e).rfind("light", 0) != 0) continue;
        const auto origin = find_vec3(e, "origin");
        if (!origin) {
            warnings.push_back("light at offset " + std::to_string(e.offset) +
                               " has no valid origin; ignored");
            continue;
        }
        lights.push_back(light_from(e, *origin, warnings));
    }
    return lights;
}

}  // namespace nq
