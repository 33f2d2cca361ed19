// The engine's services as one caller sees them: an nqr_engine table whose context is this
// object, so every call knows who is calling (the engine itself or one plugin instance) without
// globals. Each loaded plugin gets one of its own; it must outlive the plugin's instance.
#pragma once

#include "host/owner.h"
#include "nqr_renderer.h"
#include "plugin/engine_services.h"

namespace nq {

class ServiceTable {
  public:
    ServiceTable(EngineServices& services, OwnerId owner);
    ServiceTable(const ServiceTable&) = delete;
    ServiceTable& operator=(const ServiceTable&) = delete;

    const nqr_engine& table() const { return table_; }
    OwnerId owner() const { return owner_; }
    EngineServices& services() const { return services_; }

    // Logs through the table, as a plugin would.
    void log(int level, const char* text) const { table_.log(table_.context, level, text); }

  private:
    EngineServices& services_;
    OwnerId owner_;
    nqr_engine table_{};
};

}  // namespace nq
