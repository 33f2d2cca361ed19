#include "plugin/plugin_library.h"

#include <dlfcn.h>

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <utility>

#include "plugin/table_checks.h"

namespace nq {

namespace {

// The smallest 2.x table: everything up to menu_settings (ABI 2.0).
constexpr size_t kMinRendererSize = offsetof(nqr_renderer, num_menu_settings) + sizeof(uint32_t);

std::string hex(uint32_t v) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%08x", v);
    return buf;
}

std::string mismatch(uint32_t plugin_version) {
    return "ABI version mismatch: plugin built for " + hex(plugin_version) + ", engine speaks " +
           hex(NQR_ABI_VERSION) + " (and loads 1.x plugins)";
}

}  // namespace

std::string validate_renderer_table(const nqr_renderer* table) {
    if (!table) return "the plugin refused to load (its entry point returned NULL)";
    if (NQR_ABI_MAJOR(table->abi_version) != NQR_ABI_VERSION_MAJOR) {
        return mismatch(table->abi_version);
    }
    return check_table_basics(*table, kMinRendererSize);
}

PluginLibrary::PluginLibrary(void* handle, std::string path, EngineServices& services,
                             OwnerId owner)
    : handle_(handle), path_(std::move(path)), services_(services, owner) {}

Result<std::unique_ptr<PluginLibrary>> PluginLibrary::open(const std::string& path,
                                                           EngineServices& services,
                                                           OwnerId owner) {
    // RTLD_LOCAL: two plugins (old and new during a swap) may define the same symbols.
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
        const char* why = dlerror();
        return Error{path, 0, std::string("cannot load plugin: ") + (why ? why : "unknown")};
    }
    std::unique_ptr<PluginLibrary> lib(new PluginLibrary(handle, path, services, owner));
    void* entry = dlsym(handle, NQR_ENTRY_POINT);
    if (!entry) {
        return Error{path, 0, std::string("not a renderer plugin: no ") + NQR_ENTRY_POINT +
                                  " symbol"};
    }
    const nqr_renderer* table =
        reinterpret_cast<nqr_get_renderer_fn>(entry)(NQR_ABI_VERSION, &lib->services_.table());
    if (!table || NQR_ABI_MAJOR(table->abi_version) == 1) {
        // A 1.x plugin refuses a 2.0 engine, or answers as 1.x: ask again as 1.5.
        if (std::string why = lib->accept_legacy(entry); !why.empty()) {
            return Error{path, 0, why};
        }
        return lib;
    }
    if (std::string why = validate_renderer_table(table); !why.empty()) {
        return Error{path, 0, why};
    }
    std::memcpy(&lib->table_, table, std::min<size_t>(table->size, sizeof(nqr_renderer)));
    lib->table_.size = sizeof(nqr_renderer);
    lib->name_ = table->name;
    return lib;
}

std::string PluginLibrary::accept_legacy(void* entry) {
    legacy_engine_ = legacy_services(services_);
    const nqr1_renderer* table = [&] {
        LegacyCallScope scope(&services_);
        return reinterpret_cast<nqr1_get_renderer_fn>(entry)(NQR1_ABI_VERSION, &legacy_engine_);
    }();
    if (table && NQR_ABI_MAJOR(table->abi_version) != 1) return mismatch(table->abi_version);
    if (std::string why = validate_legacy_table(table); !why.empty()) return why;
    legacy_ = std::make_unique<LegacyRenderer>(*table, legacy_engine_, services_);
    table_ = legacy_->table();
    name_ = table_.name;
    return {};
}

bool PluginLibrary::init() {
    if (legacy_) {
        self_ = legacy_->init() ? legacy_.get() : nullptr;
    } else {
        self_ = table_.init(&services_.table());
    }
    return self_ != nullptr;
}

void PluginLibrary::shutdown() {
    if (!self_) return;
    table_.shutdown(std::exchange(self_, nullptr));
}

PluginLibrary::~PluginLibrary() {
    shutdown();
    legacy_.reset();
    if (handle_) dlclose(handle_);
}

}  // namespace nq
