// Loads renderer plugins by name, hot-swaps them, and hands them the engine's services.
//
// Swap protocol (r_plugin <name>): the new library is opened, validated and init()ialised while
// the old one still runs; every loaded model is registered with it; only then is the old one
// shut down and unloaded. Any failure on the way — missing file, wrong ABI, refusing entry
// point, failing init — leaves the current renderer untouched and returns the reason.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "host/owner.h"
#include "nqr_renderer.h"
#include "plugin/engine_services.h"
#include "plugin/plugin_library.h"
#include "plugin/service_table.h"

namespace nq {

struct PluginInfo {
    std::string name;  // "classic" for nqr_classic.so
    std::string path;
};

class PluginHost {
public:
  // `plugin_dir` holds nqr_<name>.so files.
  PluginHost(EngineServices& services, std::string plugin_dir);
  ~PluginHost();
  PluginHost(const PluginHost&) = delete;
  PluginHost& operator=(const PluginHost&) = delete;

  // Plugins found in the plugin directory, sorted by name.
  std::vector<PluginInfo> available() const;

  // Loads, initialises and activates `name`; returns "" on success, else why it failed (the
  // previous renderer, if any, stays active).
  std::string load(std::string_view name);
  // Shuts the active plugin down and unloads it.
  void unload();

  // The active plugin's table and the instance its hooks take as `self`.
  const nqr_renderer* active() const { return active_ ? &active_->table() : nullptr; }
  void* active_self() const { return active_ ? active_->self() : nullptr; }
  std::string active_name() const { return active_ ? active_->name() : std::string(); }
  const std::string& plugin_dir() const { return plugin_dir_; }
  // The services as the engine itself calls them (its own default drawers).
  const ServiceTable& engine_services() const { return engine_services_; }

  // The engine's loaded models: registered with the active plugin now and with every plugin
  // loaded later. Pointers must stay valid until release_model / clear_models.
  void register_model(const nqr_model* model);
  void release_model(nqr_model_id id);
  void clear_models();
  const std::vector<const nqr_model*>& models() const { return models_; }

  // Number of successful loads so far (for tests and diagnostics).
  uint32_t load_count() const { return load_count_; }

private:
    std::string plugin_path(std::string_view name) const;
    void shutdown(std::unique_ptr<PluginLibrary>& lib);

    EngineServices& services_;
    std::string plugin_dir_;
    ServiceTable engine_services_;
    std::unique_ptr<PluginLibrary> active_;
    std::vector<const nqr_model*> models_;
    OwnerId next_owner_ = 1;
    uint32_t load_count_ = 0;
};

// Plugin names are file-name stems: letters, digits, '_' and '-' only (no paths).
bool is_valid_plugin_name(std::string_view name);

}  // namespace nq
