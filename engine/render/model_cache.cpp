#include "render/model_cache.h"

#include <algorithm>
#include <cctype>
#include <utility>

#include "formats/mdl.h"
#include "formats/model_format.h"
#include "formats/spr.h"
#include "render/lighting_rgb.h"
#include "render/placeholder_model.h"

namespace nq {

namespace {

std::string lower_case(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

// "*12" -> 12; 0 when `name` is not a submodel reference.
size_t submodel_number(const std::string& name) {
    if (name.size() < 2 || name[0] != '*' || name.size() > 10) return 0;
    size_t n = 0;
    for (size_t i = 1; i < name.size(); ++i) {
        if (!std::isdigit(static_cast<unsigned char>(name[i]))) return 0;
        n = n * 10 + static_cast<size_t>(name[i] - '0');
    }
    return n;
}

}  // namespace

ModelCache::ModelCache(FileReader reader) : reader_(std::move(reader)) {}

void ModelCache::clear() {
    models_.clear();
    ids_.clear();
    world_id_ = 0;
}

std::vector<std::string> ModelCache::take_warnings() {
    return std::exchange(warnings_, {});
}

nqr_model_id ModelCache::add(std::unique_ptr<RenderModel> model) {
    const auto id = static_cast<nqr_model_id>(models_.size() + 1);
    model->set_id(id);
    ids_[lower_case(model->name())] = id;
    models_.push_back(std::move(model));
    return id;
}

nqr_model_id ModelCache::find(const std::string& name) const {
    const auto it = ids_.find(lower_case(name));
    return it == ids_.end() ? 0 : it->second;
}

const RenderModel* ModelCache::get(nqr_model_id id) const {
    return id >= 1 && id <= models_.size() ? models_[id - 1].get() : nullptr;
}

void ModelCache::note_warnings(const std::string& name, const std::vector<std::string>& warnings) {
    for (const std::string& w : warnings) warnings_.push_back(name + ": " + w);
}

Result<std::shared_ptr<const BrushModelData>> ModelCache::load_brush_data(const std::string& name) {
    auto bytes = reader_(name);
    if (!bytes) return bytes.error();
    return brush_data_from(*bytes, name);
}

Result<std::shared_ptr<const BrushModelData>> ModelCache::brush_data_from(
    std::span<const uint8_t> bytes, const std::string& name) {
    auto bsp = parse_bsp(bytes, name);
    if (!bsp) return bsp.error();
    const std::string lit_name = lit_name_for(name);
    auto lit = reader_(lit_name);  // optional: a missing .lit is the normal case
    const std::vector<uint8_t> no_lit;
    auto data = BrushModelData::build(std::move(*bsp), lit ? *lit : no_lit, lit_name);
    note_warnings(name, data->warnings());
    return data;
}

Result<nqr_model_id> ModelCache::load_world(const std::string& map_name) {
    clear();
    auto data = load_brush_data(map_name);
    if (!data) return data.error();
    const size_t submodels = (*data)->bsp().models.size();
    world_id_ = add(RenderModel::brush(map_name, *data, 0));
    for (size_t i = 1; i < submodels; ++i) {
        add(RenderModel::brush("*" + std::to_string(i), *data, i));
    }
    return world_id_;
}

nqr_model_id ModelCache::load(const std::string& name) {
    if (const nqr_model_id id = find(name)) return id;
    return add(load_model(name));
}

std::unique_ptr<RenderModel> ModelCache::placeholder(const std::string& name,
                                                     const std::string& why) {
    warnings_.push_back(name + ": " + why + "; drawing a placeholder box");
    return RenderModel::alias(name, make_placeholder_alias(), true);
}

std::unique_ptr<RenderModel> ModelCache::load_submodel(const std::string& name) {
    // Registered by load_world when they exist, so reaching here means they do not.
    return placeholder(name, world_id_ ? "the world has no such inline model" : "no world loaded");
}

// The file's first bytes decide what it is (as Quake's Mod_ForName), not its name; a name that
// says otherwise only warns, so a ".mdl" that is really a sprite still draws.
std::unique_ptr<RenderModel> ModelCache::load_model(const std::string& name) {
    if (submodel_number(name) > 0) return load_submodel(name);
    auto bytes = reader_(name);
    if (!bytes) return placeholder(name, bytes.error().to_string());
    const ModelFormat format = identify_model(*bytes);
    if (format == ModelFormat::unknown) {
        return placeholder(name, "offset 0: not a model (" + describe_model_magic(*bytes) +
                                     "; expected \"IDPO\", \"IDSP\" or a BSP version)");
    }
    const ModelFormat named = model_format_by_extension(name);
    if (named != format) {
        warnings_.push_back(name + ": its content is a " + model_format_name(format) +
                            ", whatever its name says; loaded as one");
    }
    switch (format) {
        case ModelFormat::brush: {
            auto data = brush_data_from(*bytes, name);
            if (!data) return placeholder(name, data.error().to_string());
            return RenderModel::brush(name, *data, 0);
        }
        case ModelFormat::alias: {
            auto mdl = parse_mdl(*bytes, name);
            if (!mdl) return placeholder(name, mdl.error().to_string());
            note_warnings(name, mdl->warnings);
            return RenderModel::alias(name, AliasModelData::build(std::move(*mdl)));
        }
        default: {
            auto spr = parse_spr(*bytes, name);
            if (!spr) return placeholder(name, spr.error().to_string());
            note_warnings(name, spr->warnings);
            return RenderModel::sprite(name, SpriteModelData::build(std::move(*spr)));
        }
    }
}

}  // namespace nq
