#include "server/server_level.h"

#include <algorithm>

namespace nq::server {

ServerLevel::ServerLevel(ServerHost& host_, std::unique_ptr<vm::Vm> vm_, ProgsLayout layout_)
    : host(host_),
      vm(std::move(vm_)),
      layout(layout_),
      world(*vm, layout),
      game{*vm, layout, world, edicts, {}} {}

int ServerLevel::model_index(std::string_view name) const {
    const auto it = std::find(model_names.begin(), model_names.end(), name);
    return it == model_names.end() ? -1 : int(it - model_names.begin());
}

int ServerLevel::model_index_of_string(int32_t string) {
    const std::string_view name = vm->string_or_empty(string);
    // The same value may be a temp string holding other text now: the name is compared too.
    if (last_model_index_ >= 0 && string == last_model_string_ &&
        name == model_names[size_t(last_model_index_)]) {
        return last_model_index_;
    }
    const int index = model_index(name);
    last_model_string_ = string;
    last_model_index_ = index;
    return index;
}

int ServerLevel::sound_index(std::string_view name) const {
    const auto it = std::find(sound_names.begin(), sound_names.end(), name);
    return it == sound_names.end() ? -1 : int(it - sound_names.begin());
}

std::span<const uint8_t> ServerLevel::pvs_of(const vm::Vec3f& point) {
    const uint32_t leaf = leaf_at(*bsp, point);
    // Leaf 0 is the solid outside: Quake gives an eye there (noclip) the "no vis" row, so
    // everything is visible from it.
    if (leaf == 0 || leaf >= bsp->leafs.size()) return {};
    if (pvs_rows_.size() != bsp->leafs.size()) {
        pvs_rows_.assign(bsp->leafs.size(), {});
        pvs_ready_.assign(bsp->leafs.size(), 0);
    }
    if (!pvs_ready_[leaf]) {
        pvs_rows_[leaf] = decompress_vis(*bsp, leaf);
        pvs_ready_[leaf] = 1;
    }
    return pvs_rows_[leaf];
}

CollisionModel load_collision_model(ServerLevel& level, std::string_view name) {
    if (!name.empty() && name.front() == '*') {
        const int sub = std::atoi(std::string(name.substr(1)).c_str());
        if (sub > 0 && size_t(sub) < level.bsp->models.size()) {
            return {level.bsp.get(), size_t(sub)};
        }
        level.host.print("bad submodel " + std::string(name) + "\n");
        return {};
    }
    const bool is_bsp = name.size() > 4 && name.substr(name.size() - 4) == ".bsp";
    if (!is_bsp) return {};
    const std::string path(name);
    auto bytes = level.host.read_file(path);
    if (!bytes) {
        level.host.print("cannot find " + path + "\n");
        return {};
    }
    auto bsp = parse_bsp(*bytes, path);
    if (!bsp) {
        level.host.print(bsp.error().to_string() + "\n");
        return {};
    }
    level.model_bsps.push_back(std::make_shared<const Bsp>(std::move(*bsp)));
    return {level.model_bsps.back().get(), 0};
}

}  // namespace nq::server
