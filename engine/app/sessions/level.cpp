#include "app/sessions/level.h"

#include <algorithm>
#include <chrono>

#include "client/model_info.h"
#include "formats/entities.h"

namespace nq {

namespace {

ModelInfo client_model_info(const RenderModel* model) {
    if (!model) return brush_model_info();
    if (model->alias_data()) return model_info_from_mdl(model->alias_data()->mdl());
    if (model->sprite_data()) return model_info_from_spr(model->sprite_data()->spr());
    return brush_model_info();
}

}  // namespace

void Level::clear() {
    if (baking_.valid()) baking_.wait();  // it reads the world that cache_ is about to drop
    baking_ = {};
    light_entities_.clear();
    occlusion_.reset();
    occluders_.reset();
    culler_.reset();
    lights_.reset();
    ambient_.reset();
    ids_.clear();
    model_names_.clear();
    model_info_.clear();
    world_ = nullptr;
    cache_.clear();
}

Result<bool> Level::load(ClientState& client) {
    clear();
    auto names = client.model_names();
    // Index 0 is unused; precache index 1 is the map.
    if (names.size() < 2 || names[1].empty()) {
        return Error{"serverinfo", 0, "the server named no world model"};
    }
    auto world = cache_.load_world(names[1]);
    if (!world) return world.error();
    world_ = cache_.get(world.value());
    start_ambient_bake(*world_->brush_data());
    ids_.assign(names.size(), 0);
    std::vector<ModelInfo> info(names.size());
    for (size_t i = 0; i < names.size(); ++i) {
        if (names[i].empty()) continue;
        ids_[i] = i == 1 ? world.value() : cache_.load(names[i]);
        info[i] = client_model_info(cache_.get(ids_[i]));
    }
    model_names_.assign(names.begin(), names.end());
    model_info_ = info;
    client.set_model_info(std::move(info));

    const BrushModelData* data = world_->brush_data();
    culler_ = std::make_unique<WorldCuller>(data->bsp());
    occluders_ = std::make_unique<OccluderMesh>(data->abi(), bsp_model_ranges(data->bsp()));
    occlusion_ = std::make_unique<OcclusionCuller>(*occluders_);
    auto entities = parse_entities(data->bsp().entities, names[1], data->bsp().entities_offset);
    if (entities) {
        light_entities_ = find_light_entities(entities.value(), warnings_);
    } else {
        warnings_.push_back(entities.error().to_string());
    }
    return true;
}

// The bake reads only the world's BSP and lighting (held by cache_ until clear(), which waits
// for it) and its own copy of the palette's reflectivities.
void Level::start_ambient_bake(const BrushModelData& data) {
    std::vector<glm::vec3> reflectivity = texture_reflectivity(data.bsp(), palette_);
    baking_ = std::async(std::launch::async, [&data, reflectivity = std::move(reflectivity)] {
        const auto start = std::chrono::steady_clock::now();
        BakedField baked{AmbientCubeField::bake(data.bsp(), data.lighting_rgb(), reflectivity),
                         0.0};
        baked.seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return baked;
    });
}

void Level::finish_ambient_bake() const {
    if (!baking_.valid()) return;
    BakedField baked = baking_.get();
    ambient_ = std::make_unique<AmbientCubeField>(std::move(baked.field));
    ambient_bake_seconds_ = baked.seconds;
    const BrushModelData* data = world_->brush_data();
    lights_ = std::make_unique<LightSampler>(data->bsp(), data->lighting_rgb(),
                                             std::move(light_entities_), ambient_.get());
    light_entities_.clear();
}

bool Level::holds(std::span<const std::string> model_names) const {
    return loaded() && std::equal(model_names.begin(), model_names.end(), model_names_.begin(),
                                  model_names_.end());
}

nqr_model_id Level::model_id(int index) const {
    return index >= 0 && static_cast<size_t>(index) < ids_.size() ? ids_[index] : 0;
}

uint32_t Level::model_kind(nqr_model_id id) const {
    const RenderModel* m = cache_.get(id);
    return m ? m->kind() : 0;
}

const Bsp* Level::world_bsp() const {
    return world_ && world_->brush_data() ? &world_->brush_data()->bsp() : nullptr;
}

std::vector<std::string> Level::take_warnings() {
    std::vector<std::string> out = std::move(warnings_);
    warnings_.clear();
    for (auto& w : cache_.take_warnings()) out.push_back(std::move(w));
    return out;
}

}  // namespace nq
