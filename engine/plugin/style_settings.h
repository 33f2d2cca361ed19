// The active style's main settings (nqr_renderer.menu_settings, ABI 1.3) copied out of the
// plugin's memory and checked, for the engine's Options menu. A plugin's table is untrusted:
// entries with a short size, no cvar name or label, an unknown kind, a range that is not
// finite and increasing, or a choice list without names are dropped with a reason.
#pragma once

#include <string>
#include <vector>

#include "nqr_renderer.h"

namespace nq {

enum class StyleSettingKind { Toggle, Range, Choice };

struct StyleSetting {
    std::string cvar;
    std::string label;
    StyleSettingKind kind = StyleSettingKind::Toggle;
    float min = 0, max = 1, step = 1;
    std::vector<std::string> choices;  // Choice: the name of each value 0..n-1
};

struct StyleSettings {
    std::vector<StyleSetting> settings;
    std::vector<std::string> dropped;  // why each refused entry was left out
};

// More than this many entries, or choices per entry, are no menu: the rest are dropped.
inline constexpr uint32_t kMaxStyleSettings = 32;
inline constexpr uint32_t kMaxStyleChoices = 16;

StyleSettings read_style_settings(const nqr_renderer& table);

}  // namespace nq
