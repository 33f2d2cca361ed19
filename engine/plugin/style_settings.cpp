#include "plugin/style_settings.h"

#include <cmath>
#include <cstddef>

namespace nq {
namespace {

constexpr size_t kSettingSize = offsetof(nqr_menu_setting, num_choices) + sizeof(uint32_t);
constexpr uint32_t kMaxSettingStride = 1024;  // far beyond any minor version's growth
constexpr size_t kTableSizeWithMenu = offsetof(nqr_renderer, num_menu_settings) + sizeof(uint32_t);

// Why `entry` cannot be shown, or "" when it can.
std::string refusal(const nqr_menu_setting& entry) {
    if (entry.size < kSettingSize)
        return "its size " + std::to_string(entry.size) + " is too small";
    if (!entry.cvar || !*entry.cvar || !entry.label || !*entry.label) return "no cvar or label";
    switch (entry.kind) {
        case NQR_MENU_TOGGLE:
            return {};
        case NQR_MENU_RANGE:
            if (!std::isfinite(entry.min) || !std::isfinite(entry.max) ||
                !std::isfinite(entry.step) || !(entry.min < entry.max) || !(entry.step > 0)) {
                return "its range is not min < max with a step above 0";
            }
            return {};
        case NQR_MENU_CHOICE:
            if (!entry.choices || entry.num_choices == 0 || entry.num_choices > kMaxStyleChoices) {
                return "it has no choices, or more than " + std::to_string(kMaxStyleChoices);
            }
            for (uint32_t i = 0; i < entry.num_choices; ++i) {
                if (!entry.choices[i]) return "choice " + std::to_string(i) + " has no name";
            }
            return {};
        default:
            return "unknown kind " + std::to_string(entry.kind);
    }
}

StyleSetting copy_setting(const nqr_menu_setting& entry) {
    StyleSetting out;
    out.cvar = entry.cvar;
    out.label = entry.label;
    out.kind = entry.kind == NQR_MENU_RANGE    ? StyleSettingKind::Range
               : entry.kind == NQR_MENU_CHOICE ? StyleSettingKind::Choice
                                               : StyleSettingKind::Toggle;
    out.min = entry.min;
    out.max = entry.max;
    out.step = entry.step;
    if (out.kind == StyleSettingKind::Toggle) {
        out.min = 0;
        out.max = 1;
        out.step = 1;
    }
    if (out.kind == StyleSettingKind::Choice) {
        out.min = 0;
        out.max = float(entry.num_choices - 1);
        out.step = 1;
        for (uint32_t i = 0; i < entry.num_choices; ++i) out.choices.emplace_back(entry.choices[i]);
    }
    return out;
}

}  // namespace

StyleSettings read_style_settings(const nqr_renderer& table) {
    StyleSettings out;
    if (table.size < kTableSizeWithMenu || !table.menu_settings) return out;
    uint32_t count = table.num_menu_settings;
    if (count > kMaxStyleSettings) {
        out.dropped.push_back(std::to_string(count - kMaxStyleSettings) + " settings beyond " +
                              std::to_string(kMaxStyleSettings));
        count = kMaxStyleSettings;
    }
    if (count == 0) return out;
    const uint32_t stride = table.menu_settings->size;
    if ((stride < kSettingSize || stride > kMaxSettingStride)) {
        out.dropped.push_back("every setting: the entries' size " + std::to_string(stride) +
                              " is not plausible");
        return out;
    }
    for (uint32_t i = 0; i < count; ++i) {
        const nqr_menu_setting& entry = *nqr_at(nqr_menu_setting, table.menu_settings, i);
        if (std::string why = refusal(entry); !why.empty()) {
            out.dropped.push_back("setting " + std::to_string(i) + ": " + why);
            continue;
        }
        out.settings.push_back(copy_setting(entry));
    }
    return out;
}

}  // namespace nq
