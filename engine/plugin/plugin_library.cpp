#include "plugin/plugin_library.h"

#include <dlfcn.h>

#include <cstddef>
#include <cstring>

namespace nq {

namespace {

// The smallest table a 1.x plugin can return: everything up to end_frame (ABI 1.0).
constexpr size_t kMinRendererSize = offsetof(nqr_renderer, end_frame) + sizeof(void*);

std::string hex(uint32_t v) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%08x", v);
    return buf;
}

}  // namespace

std::string validate_renderer_table(const nqr_renderer* table) {
    if (!table) return "the plugin refused to load (its entry point returned NULL)";
    if (NQR_ABI_MAJOR(table->abi_version) != NQR_ABI_VERSION_MAJOR) {
        return "ABI version mismatch: plugin built for " + hex(table->abi_version) +
               ", engine speaks " + hex(NQR_ABI_VERSION) + " (major versions must match)";
    }
    if (table->size < kMinRendererSize) {
        return "function table too small (" + std::to_string(table->size) + " bytes, need " +
               std::to_string(kMinRendererSize) + ")";
    }
    if (!table->init || !table->shutdown) return "the plugin has no init or shutdown function";
    if (!table->name || !*table->name) return "the plugin has no name";
    return {};
}

Result<std::unique_ptr<PluginLibrary>> PluginLibrary::open(const std::string& path,
                                                           const nqr_engine* engine,
                                                           OwnerId owner) {
    // RTLD_LOCAL: two plugins (old and new during a swap) may define the same symbols.
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
        const char* why = dlerror();
        return Error{path, 0, std::string("cannot load plugin: ") + (why ? why : "unknown")};
    }
    std::unique_ptr<PluginLibrary> lib(new PluginLibrary(handle, path, owner));
    auto entry = reinterpret_cast<nqr_get_renderer_fn>(dlsym(handle, NQR_ENTRY_POINT));
    if (!entry) {
        return Error{path, 0, std::string("not a renderer plugin: no ") + NQR_ENTRY_POINT +
                                  " symbol"};
    }
    const nqr_renderer* table = entry(NQR_ABI_VERSION, engine);
    if (std::string why = validate_renderer_table(table); !why.empty()) {
        return Error{path, 0, why};
    }
    std::memcpy(&lib->table_, table, std::min<size_t>(table->size, sizeof(nqr_renderer)));
    lib->table_.size = sizeof(nqr_renderer);
    lib->name_ = table->name;
    return lib;
}

PluginLibrary::~PluginLibrary() {
    if (handle_) dlclose(handle_);
}

}  // namespace nq
