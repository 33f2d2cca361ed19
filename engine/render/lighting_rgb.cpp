#include "render/lighting_rgb.h"

namespace nq {

namespace {

std::vector<uint8_t> grey_expanded(const std::vector<uint8_t>& mono) {
    std::vector<uint8_t> rgb;
    rgb.reserve(mono.size() * 3);
    for (uint8_t v : mono) rgb.insert(rgb.end(), {v, v, v});
    return rgb;
}

}  // namespace

LightingRgb build_lighting_rgb(const Bsp& bsp, std::span<const uint8_t> lit_file,
                               const std::string& lit_name) {
    LightingRgb out;
    if (bsp.lighting.empty()) return out;
    if (!lit_file.empty()) {
        auto lit = parse_lit(lit_file, lit_name, bsp.lighting.size());
        if (!lit) {
            out.warnings.push_back(lit.error().to_string() + " (coloured light ignored)");
        } else {
            for (auto& w : lit->warnings) out.warnings.push_back(lit_name + ": " + w);
            if (!lit->rgb.empty()) {
                out.rgb = std::move(lit->rgb);
                out.from_lit = true;
                return out;
            }
        }
    }
    out.rgb = grey_expanded(bsp.lighting);
    return out;
}

std::string lit_name_for(const std::string& map_name) {
    const size_t dot = map_name.find_last_of('.');
    const size_t slash = map_name.find_last_of('/');
    const bool has_extension =
        dot != std::string::npos && (slash == std::string::npos || dot > slash);
    return (has_extension ? map_name.substr(0, dot) : map_name) + ".lit";
}

}  // namespace nq
