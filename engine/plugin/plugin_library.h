// One loaded renderer plugin: the shared library, its services (a ServiceTable of its own), its
// validated function table and, once init() succeeded, its instance. Loading checks everything
// the ABI promises before a single hook is trusted. A 2.x plugin is called directly; a 1.x
// plugin through LegacyRenderer, which presents the same 2.0 table.
#pragma once

#include <memory>
#include <string>

#include "common/result.h"
#include "host/owner.h"
#include "nqr_renderer.h"
#include "nqr_renderer_1x.h"
#include "plugin/engine_services.h"
#include "plugin/legacy_renderer.h"
#include "plugin/service_table.h"

namespace nq {

class PluginLibrary {
  public:
    // dlopen()s `path`, finds NQR_ENTRY_POINT, calls it (for ABI 2.0; when the plugin refuses
    // or answers with a 1.x table, again for 1.5) and validates the returned table (non-NULL,
    // ABI major, size, required hooks, name). Does not call init().
    static Result<std::unique_ptr<PluginLibrary>> open(const std::string& path,
                                                       EngineServices& services, OwnerId owner);
    ~PluginLibrary();  // shuts the instance down if there is one, then dlclose()s

    PluginLibrary(const PluginLibrary&) = delete;
    PluginLibrary& operator=(const PluginLibrary&) = delete;

    // Creates the plugin's instance; false when its init refused (it logged why).
    bool init();
    // Ends the instance (no-op without one).
    void shutdown();

    // The plugin's table, copied into host memory (fields an older plugin did not have are
    // NULL), and the instance its hooks take as `self`.
    const nqr_renderer& table() const { return table_; }
    void* self() const { return self_; }
    const std::string& name() const { return name_; }
    const std::string& path() const { return path_; }
    OwnerId owner() const { return services_.owner(); }
    // The ABI version the plugin was built for (1.x plugins run through the adapter).
    uint32_t abi_version() const { return table_.abi_version; }

  private:
    PluginLibrary(void* handle, std::string path, EngineServices& services, OwnerId owner);
    std::string accept_legacy(void* entry);

    void* handle_ = nullptr;
    std::string path_;
    std::string name_;
    ServiceTable services_;
    nqr1_engine legacy_engine_{};  // what a 1.x plugin was given
    std::unique_ptr<LegacyRenderer> legacy_;
    nqr_renderer table_{};
    void* self_ = nullptr;
};

// Checks a 2.x table a plugin returned against this engine's ABI; "" when acceptable,
// otherwise the reason (shown to the user).
std::string validate_renderer_table(const nqr_renderer* table);

}  // namespace nq
