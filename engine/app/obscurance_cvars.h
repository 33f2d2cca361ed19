// The vo_* cvars of the engine-wide volumetric obscurance pass (nprlib/obscurance), usable
// under every renderer style; documented in docs/console.md and docs/obscurance.md.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>

#include "host/cvar_registry.h"
#include "obscurance/obscurance_settings.h"

namespace nq {

class ObscuranceCvars {
  public:
    // Registers the cvars; `warn` reports values that cannot be used (e.g. an unknown vo_mode).
    void register_cvars(CvarRegistry& cvars, std::function<void(const std::string&)> warn);

    // The settings as the cvars say now; re-read only when one of them changed.
    const npr::obscurance::ObscuranceSettings& settings();

  private:
    enum Index {
        enable,
        mode,
        radius,
        radius2,
        dual,
        thickness,
        strength,
        normal,
        blur,
        half,
        show,
        sample_set,
        sample_count,
        compute,
        shift,
        count
    };
    void read();

    std::array<Cvar*, count> cvars_{};
    std::array<uint32_t, count> seen_{};
    npr::obscurance::ObscuranceSettings settings_;
    std::function<void(const std::string&)> warn_;
};

}  // namespace nq
