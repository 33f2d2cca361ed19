#include "render/render_model.h"

#include <algorithm>
#include <cmath>

namespace nq {

namespace {

nqr_model blank_model(uint32_t kind) {
    nqr_model m{};
    m.size = sizeof(nqr_model);
    m.kind = kind;
    return m;
}

}  // namespace

void RenderModel::set_bounds(const float mins[3], const float maxs[3]) {
    // Radius of the farthest box corner from the origin, as Quake's RadiusFromBounds.
    float squared = 0;
    for (int i = 0; i < 3; ++i) {
        model_.mins[i] = mins[i];
        model_.maxs[i] = maxs[i];
        const float far = std::max(std::fabs(mins[i]), std::fabs(maxs[i]));
        squared += far * far;
    }
    model_.radius = std::sqrt(squared);
}

std::unique_ptr<RenderModel> RenderModel::brush(std::string name,
                                                std::shared_ptr<const BrushModelData> data,
                                                size_t submodel) {
    std::unique_ptr<RenderModel> m(new RenderModel());
    m->name_ = std::move(name);
    m->model_ = blank_model(NQR_MODEL_BRUSH);
    m->model_.name = m->name_.c_str();
    m->model_.brush = &data->abi();
    const Bsp& bsp = data->bsp();
    if (submodel < bsp.models.size()) {
        const BspModel& bm = bsp.models[submodel];
        m->set_bounds(bm.mins.data(), bm.maxs.data());
        m->model_.first_surface = bm.first_face;
        m->model_.num_surfaces = bm.num_faces;
    }
    m->brush_ = std::move(data);
    return m;
}

std::unique_ptr<RenderModel> RenderModel::alias(std::string name,
                                                std::shared_ptr<const AliasModelData> data,
                                                bool placeholder) {
    std::unique_ptr<RenderModel> m(new RenderModel());
    m->name_ = std::move(name);
    m->placeholder_ = placeholder;
    m->model_ = blank_model(NQR_MODEL_ALIAS);
    m->model_.name = m->name_.c_str();
    m->model_.alias = &data->abi();
    m->set_bounds(&data->mins()[0], &data->maxs()[0]);
    m->model_.radius = data->radius();  // exact, tighter than the box corner
    m->alias_ = std::move(data);
    return m;
}

std::unique_ptr<RenderModel> RenderModel::sprite(std::string name,
                                                 std::shared_ptr<const SpriteModelData> data) {
    std::unique_ptr<RenderModel> m(new RenderModel());
    m->name_ = std::move(name);
    m->model_ = blank_model(NQR_MODEL_SPRITE);
    m->model_.name = m->name_.c_str();
    m->model_.sprite = &data->abi();
    const float r = data->radius();
    const float mins[3] = {-r, -r, -r}, maxs[3] = {r, r, r};
    m->set_bounds(mins, maxs);
    m->model_.radius = r;
    m->sprite_ = std::move(data);
    return m;
}

}  // namespace nq
