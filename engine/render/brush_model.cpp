#include "render/brush_model.h"

namespace nq {

std::shared_ptr<const BrushModelData> BrushModelData::build(Bsp bsp,
                                                            std::span<const uint8_t> lit_file,
                                                            const std::string& lit_name) {
    std::shared_ptr<BrushModelData> data(new BrushModelData());
    data->bsp_ = std::move(bsp);
    const Bsp& map = data->bsp_;
    data->geometry_ = build_brush_geometry(map);
    data->textures_ = build_brush_textures(map);
    data->lighting_ = build_lighting_rgb(map, lit_file, lit_name);

    auto& w = data->warnings_;
    w = map.warnings;
    w.insert(w.end(), data->geometry_.warnings.begin(), data->geometry_.warnings.end());
    w.insert(w.end(), data->textures_.warnings.begin(), data->textures_.warnings.end());
    w.insert(w.end(), data->lighting_.warnings.begin(), data->lighting_.warnings.end());
    data->link_abi();
    return data;
}

void BrushModelData::link_abi() {
    brush_ = nqr_brush_model{};
    brush_.size = sizeof(nqr_brush_model);
    brush_.num_surfaces = static_cast<uint32_t>(geometry_.surfaces.size());
    brush_.surfaces = geometry_.surfaces.empty() ? nullptr : geometry_.surfaces.data();
    brush_.num_vertices = static_cast<uint32_t>(geometry_.vertex_ids.size());
    brush_.positions = geometry_.positions.empty() ? nullptr : geometry_.positions.data();
    brush_.vertex_ids = geometry_.vertex_ids.empty() ? nullptr : geometry_.vertex_ids.data();
    brush_.num_textures = static_cast<uint32_t>(textures_.textures.size());
    brush_.textures = textures_.textures.empty() ? nullptr : textures_.textures.data();
    brush_.lighting_rgb = lighting_.rgb.empty() ? nullptr : lighting_.rgb.data();
    brush_.num_light_samples = lighting_.rgb.size() / 3;
}

}  // namespace nq
