#include "plugin/plugin_host.h"

#include <algorithm>
#include <cassert>
#include <filesystem>

namespace nq {

namespace {

// The C services table has no context argument; its trampolines find the host through these.
// `g_owner` is the plugin that is calling: the one being initialised, or else the active one.
EngineServices* g_services = nullptr;
OwnerId g_owner = kEngineOwner;

constexpr std::string_view kPrefix = "nqr_";
constexpr std::string_view kSuffix = ".so";

void c_log(int level, const char* text) { g_services->log(level, text ? text : ""); }

const nqr_cvar* c_cvar_register(const char* name, const char* default_value, uint32_t flags,
                                const char* description) {
    if (!name || !default_value) return nullptr;
    return g_services->register_cvar(g_owner, name, default_value, flags,
                                     description ? description : "");
}

void c_cvar_set(const char* name, const char* value) {
    if (name && value) g_services->set_cvar(name, value);
}

int c_command_register(const char* name, nqr_command_fn fn, void* user, const char* description) {
    if (!name || !fn) return 0;
    return g_services->register_command(g_owner, name, fn, user, description ? description : "")
               ? 1
               : 0;
}

int c_file_read(const char* path, nqr_blob* out) {
    if (!path || !out) return -1;
    auto* bytes = new std::vector<uint8_t>();
    if (!g_services->read_file(path, *bytes)) {
        delete bytes;
        *out = nqr_blob{sizeof(nqr_blob), nullptr, 0, nullptr};
        return -1;
    }
    *out = nqr_blob{sizeof(nqr_blob), bytes->data(), bytes->size(), bytes};
    return 0;
}

void c_file_free(nqr_blob* blob) {
    if (!blob) return;
    delete static_cast<std::vector<uint8_t>*>(blob->engine_private);
    *blob = nqr_blob{sizeof(nqr_blob), nullptr, 0, nullptr};
}

void* c_gl_proc_address(const char* name) {
    return name ? g_services->gl_proc_address(name) : nullptr;
}

double c_real_time() { return g_services->real_time(); }

void c_trace(const float start[3], const float end[3], nqr_trace* out) {
    if (!out) return;
    *out = nqr_trace{};
    out->size = sizeof(nqr_trace);
    out->fraction = 1.0f;
    if (start && end) g_services->trace(start, end, out);
}

void c_gpu_pass_begin(const char* name) { g_services->gpu_pass_begin(name); }
void c_gpu_pass_end() { g_services->gpu_pass_end(); }

// Sets the calling owner for the duration of a plugin call and restores it afterwards.
class OwnerScope {
public:
    explicit OwnerScope(OwnerId owner) : saved_(g_owner) { g_owner = owner; }
    ~OwnerScope() { g_owner = saved_; }

private:
    OwnerId saved_;
};

}  // namespace

bool is_valid_plugin_name(std::string_view name) {
    if (name.empty() || name.size() > 64) return false;
    return std::all_of(name.begin(), name.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
               c == '_' || c == '-';
    });
}

PluginHost::PluginHost(EngineServices& services, std::string plugin_dir)
    : services_(services), plugin_dir_(std::move(plugin_dir)) {
    assert(!g_services && "only one PluginHost at a time");
    g_services = &services_;
    engine_table_.size = sizeof(nqr_engine);
    engine_table_.abi_version = NQR_ABI_VERSION;
    engine_table_.log = c_log;
    engine_table_.cvar_register = c_cvar_register;
    engine_table_.cvar_set = c_cvar_set;
    engine_table_.command_register = c_command_register;
    engine_table_.file_read = c_file_read;
    engine_table_.file_free = c_file_free;
    engine_table_.gl_get_proc_address = c_gl_proc_address;
    engine_table_.real_time = c_real_time;
    engine_table_.trace = c_trace;
    engine_table_.palette = services_.palette();
    engine_table_.colormap = services_.colormap();
    engine_table_.gpu_pass_begin = c_gpu_pass_begin;
    engine_table_.gpu_pass_end = c_gpu_pass_end;
}

PluginHost::~PluginHost() {
    unload();
    g_services = nullptr;
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
    auto opened = [&] {
        OwnerScope scope(owner);
        return PluginLibrary::open(path, &engine_table_, owner);
    }();
    if (!opened) {
        services_.release_owner(owner);
        return opened.error().message + " (" + path + ")";
    }
    std::unique_ptr<PluginLibrary> lib = std::move(opened.value());
    {
        OwnerScope scope(owner);
        if (lib->table().init(&engine_table_) != 0) {
            services_.release_owner(owner);
            return "plugin \"" + lib->name() + "\" failed to initialise (see messages above)";
        }
        if (lib->table().register_model) {
            for (const nqr_model* m : models_) lib->table().register_model(m);
        }
    }
    shutdown(active_);
    active_ = std::move(lib);
    g_owner = active_->owner();
    ++load_count_;
    return {};
}

void PluginHost::shutdown(std::unique_ptr<PluginLibrary>& lib) {
    if (!lib) return;
    {
        OwnerScope scope(lib->owner());
        lib->table().shutdown();
    }
    services_.release_owner(lib->owner());
    lib.reset();
}

void PluginHost::unload() {
    shutdown(active_);
    g_owner = kEngineOwner;
}

void PluginHost::register_model(const nqr_model* model) {
    models_.push_back(model);
    if (active_ && active_->table().register_model) {
        OwnerScope scope(active_->owner());
        active_->table().register_model(model);
    }
}

void PluginHost::release_model(nqr_model_id id) {
    std::erase_if(models_, [id](const nqr_model* m) { return m->id == id; });
    if (active_ && active_->table().release_model) {
        OwnerScope scope(active_->owner());
        active_->table().release_model(id);
    }
}

void PluginHost::clear_models() {
    while (!models_.empty()) release_model(models_.back()->id);
}

}  // namespace nq
