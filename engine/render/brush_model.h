// A parsed map as the renderer ABI's nqr_brush_model. Owns the Bsp and every array the ABI
// struct points into; shared (read-only) by the world model and its inline submodels.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <vector>

#include "formats/bsp.h"
#include "nqr_renderer.h"
#include "render/brush_surfaces.h"
#include "render/brush_textures.h"
#include "render/lighting_rgb.h"

namespace nq {

class BrushModelData {
  public:
    // `lit_file`: the bytes of the map's .lit (empty when there is none).
    static std::shared_ptr<const BrushModelData> build(Bsp bsp,
                                                       std::span<const uint8_t> lit_file = {},
                                                       const std::string& lit_name = {});

    BrushModelData(const BrushModelData&) = delete;
    BrushModelData& operator=(const BrushModelData&) = delete;

    const nqr_brush_model& abi() const { return brush_; }
    const Bsp& bsp() const { return bsp_; }
    // RGB samples (3 per sample of Bsp::lighting); empty when the map is unlit.
    std::span<const uint8_t> lighting_rgb() const { return lighting_.rgb; }
    bool has_coloured_light() const { return lighting_.from_lit; }
    // The parser's warnings, then animation-chain and .lit findings.
    const std::vector<std::string>& warnings() const { return warnings_; }

  private:
    BrushModelData() = default;
    void link_abi();

    Bsp bsp_;
    BrushGeometry geometry_;
    BrushTextures textures_;
    LightingRgb lighting_;
    nqr_brush_model brush_{};
    std::vector<std::string> warnings_;
};

}  // namespace nq
