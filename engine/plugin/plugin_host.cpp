#include "plugin/plugin_host.h"

#include <algorithm>
#include <filesystem>

namespace nq {

namespace {

constexpr std::string_view kPrefix = "nqr_";
constexpr std::string_view kSuffix = ".so";

}  // namespace

bool is_valid_plugin_name(std::string_view name) {
    if (name.empty() || name.size() > 64) return false;
    return std::all_of(name.begin(), name.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
               c == '_' || c == '-';
    });
}

PluginHost::PluginHost(EngineServices& services, std::string plugin_dir)
    : services_(services),
      plugin_dir_(std::move(plugin_dir)),
      engine_services_(services, kEngineOwner) {}

PluginHost::~PluginHost() {
    unload();
}

std::vector<PluginInfo> PluginHost::available() const {
    std::vector<PluginInfo> out;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(plugin_dir_, ec)) {
        std::string file = entry.path().filename().string();
        if (file.size() <= kPrefix.size() + kSuffix.size() || !file.starts_with(kPrefix) ||
            !file.ends_with(kSuffix)) {
            continue;
        }
        std::string name = file.substr(kPrefix.size(), file.size() - kPrefix.size() - kSuffix.size());
        if (is_valid_plugin_name(name)) out.push_back({name, entry.path().string()});
    }
    std::sort(out.begin(), out.end(),
              [](const PluginInfo& a, const PluginInfo& b) { return a.name < b.name; });
    return out;
}

std::string PluginHost::plugin_path(std::string_view name) const {
    return (std::filesystem::path(plugin_dir_) /
            (std::string(kPrefix) + std::string(name) + std::string(kSuffix)))
        .string();
}

std::string PluginHost::load(std::string_view name) {
    if (!is_valid_plugin_name(name)) {
        return "invalid plugin name \"" + std::string(name) + "\" (letters, digits, _ and - only)";
    }
    std::string path = plugin_path(name);
    if (!std::filesystem::exists(path)) {
        return "no renderer plugin \"" + std::string(name) + "\" (looked for " + path + ")";
    }
    OwnerId owner = next_owner_++;
    auto opened = PluginLibrary::open(path, services_, owner);
    if (!opened) {
        services_.release_owner(owner);
        return opened.error().message + " (" + path + ")";
    }
    std::unique_ptr<PluginLibrary> lib = std::move(opened.value());
    if (!lib->init()) {
        services_.release_owner(owner);
        return "plugin \"" + lib->name() + "\" failed to initialise (see messages above)";
    }
    if (lib->table().register_model) {
        for (const nqr_model* m : models_) lib->table().register_model(lib->self(), m);
    }
    shutdown(active_);
    active_ = std::move(lib);
    ++load_count_;
    return {};
}

void PluginHost::shutdown(std::unique_ptr<PluginLibrary>& lib) {
    if (!lib) return;
    lib->shutdown();
    services_.release_owner(lib->owner());
    lib.reset();
}

void PluginHost::unload() {
    shutdown(active_);
}

void PluginHost::register_model(const nqr_model* model) {
    models_.push_back(model);
    if (active_ && active_->table().register_model) {
        active_->table().register_model(active_->self(), model);
    }
}

void PluginHost::release_model(nqr_model_id id) {
    std::erase_if(models_, [id](const nqr_model* m) { return m->id == id; });
    if (active_ && active_->table().release_model) {
        active_->table().release_model(active_->self(), id);
    }
}

void PluginHost::clear_models() {
    while (!models_.empty()) release_model(models_.back()->id);
}

}  // namespace nq
