// The technical style's console variables: one per TechnicalSettings field, each with its
// default (the paper's value where it gives one), archived to config.cfg. The table is the single
// source: the plugin registers it, reads it into TechnicalSettings, and a test checks that
// docs/console.md lists every entry with its default.
#pragma once

#include <cstddef>
#include <span>

#include "nqr_renderer.h"
#include "technical/technical_settings.h"

namespace nq::npr::technical {

struct CvarBinding {
    const char* name;
    const char* default_value;
    const char* description;
    // Reads the cvar into its settings field.
    void (*apply)(const nqr_cvar& cvar, TechnicalSettings& settings);
};

std::span<const CvarBinding> technical_cvar_bindings();

// The style's main settings as the engine's Options menu shows them (ABI 1.3): a subset of the
// bindings above, each naming one of them.
std::span<const nqr_menu_setting> technical_menu_settings();

// Registers every binding with the engine (NQR_CVAR_ARCHIVE) and keeps the live cvars; update()
// copies changed ones into settings (cheap when nothing changed; never allocates).
class TechnicalCvars {
  public:
    void register_all(const nqr_engine& engine);
    void update(TechnicalSettings& settings);

  private:
    static constexpr size_t kMaxCvars = 64;
    const nqr_cvar* cvars_[kMaxCvars] = {};
    uint32_t seen_[kMaxCvars] = {};
    bool first_ = true;
};

}  // namespace nq::npr::technical
