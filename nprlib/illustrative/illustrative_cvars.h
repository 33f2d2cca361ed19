// The illustrative style's console variables: one per IllustrativeSettings field (plus ill_show),
// each with its default (Valve's player-material values where the paper gives none), archived to
// config.cfg. The table is the single source: the plugin registers it, reads it into the
// settings, and a test checks that docs/console.md lists every entry with its default.
#pragma once

#include <span>

#include "abi/cvar_bindings.h"
#include "illustrative/illustrative_settings.h"
#include "nqr_renderer.h"

namespace nq::npr::illustrative {

using CvarBinding = npr::CvarBinding<IllustrativeSettings>;

std::span<const CvarBinding> illustrative_cvar_bindings();

// The style's main settings as the engine's Options menu shows them (ABI 1.3).
std::span<const nqr_menu_setting> illustrative_menu_settings();

class IllustrativeCvars : public CvarSet<IllustrativeSettings> {
  public:
    IllustrativeCvars() : CvarSet(illustrative_cvar_bindings()) {}
};

}  // namespace nq::npr::illustrative
