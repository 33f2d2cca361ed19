// Runs a 1.x renderer plugin under the 2.0 engine. A 1.x plugin has no contexts: its services
// reach the calling plugin's ServiceTable through the caller set around every call into it
// (LegacyCallScope; between calls, e.g. in its console commands, the newest initialised 1.x
// plugin); and it reads the 1.x frame, with the camera and each entity's light held by value,
// which the adapter writes from the 2.0 frame into buffers kept from frame to frame (they grow
// only when a frame holds more entities than any before). Its hooks are presented as a 2.0
// table whose `self` is the adapter, so the rest of the engine calls every plugin alike.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "nqr_renderer.h"
#include "nqr_renderer_1x.h"
#include "plugin/service_table.h"

namespace nq {

// The services a 1.x plugin is given: forwarded to the caller of the moment.
nqr1_engine legacy_services(const ServiceTable& services);

// Makes `services` the 1.x caller for the scope's lifetime.
class LegacyCallScope {
  public:
    explicit LegacyCallScope(const ServiceTable* services);
    ~LegacyCallScope();
    LegacyCallScope(const LegacyCallScope&) = delete;
    LegacyCallScope& operator=(const LegacyCallScope&) = delete;

  private:
    const ServiceTable* saved_;
};

// "" when a 1.x plugin's table can be used, else why not.
std::string validate_legacy_table(const nqr1_renderer* table);

class LegacyRenderer {
  public:
    // `table` passed validate_legacy_table; `engine` (the plugin's 1.x services) and
    // `services` outlive this adapter.
    LegacyRenderer(const nqr1_renderer& table, const nqr1_engine& engine,
                   const ServiceTable& services);
    ~LegacyRenderer();
    LegacyRenderer(const LegacyRenderer&) = delete;
    LegacyRenderer& operator=(const LegacyRenderer&) = delete;

    // The plugin's init; true when it is ready.
    bool init();
    // The 2.0 face: hooks present where the plugin has them; pass this adapter as `self`.
    const nqr_renderer& table() const { return table_; }
    uint32_t abi_version() const { return legacy_.abi_version; }

    // The 1.x frame for `frame`, written once per frame number (for tests too).
    const nqr1_frame& convert(const nqr_frame& frame);

  private:
    void convert_entities(const nqr_frame& frame);
    const nqr1_entity* const* convert_list(const nqr_entity* const* list, uint32_t count,
                                           size_t& next);
    void call_shutdown();
    template <auto Hook>
    static void draw(void* self, const nqr_frame* frame);
    static void post_process(void* self, const nqr_frame* frame, const nqr_gbuffer* gbuffer);

    nqr1_renderer legacy_{};
    const nqr1_engine& engine_;
    const ServiceTable& services_;
    nqr_renderer table_{};

    nqr1_frame frame_{};
    uint64_t converted_number_ = 0;
    bool converted_any_ = false;
    std::vector<nqr1_entity> entities_;
    std::vector<const nqr1_entity*> lists_;  // the three kinds' pointer lists, one after another
};

}  // namespace nq
