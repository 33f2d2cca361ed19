// The technical style's console variables: one per TechnicalSettings field, each with its
// default (the paper's value where it gives one), archived to config.cfg. The table is the single
// source: the plugin registers it, reads it into TechnicalSettings, and a test checks that
// docs/console.md lists every entry with its default.
#pragma once

#include <span>

#include "abi/cvar_bindings.h"
#include "nqr_renderer.h"
#include "technical/technical_settings.h"

namespace nq::npr::technical {

using CvarBinding = npr::CvarBinding<TechnicalSettings>;

std::span<const CvarBinding> technical_cvar_bindings();

// The style's main settings as the engine's Options menu shows them (ABI 1.3): a subset of the
// bindings above, each naming one of them.
std::span<const nqr_menu_setting> technical_menu_settings();

// Registers every binding with the engine (NQR_CVAR_ARCHIVE) and keeps the live cvars; update()
// copies changed ones into settings (cheap when nothing changed; never allocates).
class TechnicalCvars : public CvarSet<TechnicalSettings> {
  public:
    TechnicalCvars() : CvarSet(technical_cvar_bindings()) {}
};

}  // namespace nq::npr::technical
