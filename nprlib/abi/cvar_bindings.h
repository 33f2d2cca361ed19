// A style's console variables as one table: each binding names a cvar, its default and
// description, and how its value reaches the style's settings struct. The plugin registers the
// table (archived to config.cfg) and calls update() once a frame; only cvars whose
// modified_count moved are read again, and nothing allocates. Also the small parsers the
// bindings share and the constructors of the Options-menu lines (ABI 1.3).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>

#include <glm/vec3.hpp>

#include "nqr_renderer.h"

namespace nq::npr {

template <class Settings>
struct CvarBinding {
    const char* name;
    const char* default_value;
    const char* description;
    void (*apply)(const nqr_cvar& cvar, Settings& settings);
};

template <class Settings, size_t MaxCvars = 64>
class CvarSet {
  public:
    explicit CvarSet(std::span<const CvarBinding<Settings>> bindings) : bindings_(bindings) {}

    void register_all(const nqr_engine& engine) {
        size_t i = 0;
        for (const CvarBinding<Settings>& b : bindings_) {
            if (i == MaxCvars) break;
            cvars_[i++] = engine.cvar_register
                              ? engine.cvar_register(engine.context, b.name, b.default_value,
                                                     NQR_CVAR_ARCHIVE, b.description)
                              : nullptr;
        }
        first_ = true;
    }

    void update(Settings& settings) {
        size_t i = 0;
        for (const CvarBinding<Settings>& b : bindings_) {
            if (i == MaxCvars) break;
            const nqr_cvar* cvar = cvars_[i];
            if (cvar && (first_ || cvar->modified_count != seen_[i])) {
                b.apply(*cvar, settings);
                seen_[i] = cvar->modified_count;
            }
            ++i;
        }
        first_ = false;
    }

  private:
    std::span<const CvarBinding<Settings>> bindings_;
    const nqr_cvar* cvars_[MaxCvars] = {};
    uint32_t seen_[MaxCvars] = {};
    bool first_ = true;
};

namespace cvar_parse {

inline bool flag(const nqr_cvar& c) {
    return c.value != 0.0f;
}

inline int choice(const nqr_cvar& c, int highest) {
    return std::clamp(c.integer, 0, highest);
}

// Up to N numbers separated by spaces (brackets ignored, as in "[0.3 1 8]"); missing ones repeat
// the last one read, or `fallback` when none was. Each clamped to [lo, hi].
template <int N>
void numbers(const nqr_cvar& c, float lo, float hi, float fallback, float* out) {
    const char* text = c.string ? c.string : "";
    float last = fallback;
    for (int i = 0; i < N; ++i) {
        while (*text == ' ' || *text == '[' || *text == ']' || *text == '\t') ++text;
        char* end = nullptr;
        const float v = std::strtof(text, &end);
        if (end != text) {
            last = std::clamp(v, lo, hi);
            text = end;
        }
        out[i] = last;
    }
}

// "r g b" with components 0..1; missing components repeat the last one ("0.5" is grey).
inline glm::vec3 color(const nqr_cvar& c) {
    glm::vec3 out(0.0f);
    numbers<3>(c, 0.0f, 1.0f, 0.0f, &out.x);
    return out;
}

}  // namespace cvar_parse

namespace menu_line {

constexpr nqr_menu_setting toggle(const char* cvar, const char* label) {
    return {sizeof(nqr_menu_setting), cvar, label, NQR_MENU_TOGGLE, 0, 1, 1, nullptr, 0};
}

constexpr nqr_menu_setting range(const char* cvar, const char* label, float min, float max,
                                 float step) {
    return {sizeof(nqr_menu_setting), cvar, label, NQR_MENU_RANGE, min, max, step, nullptr, 0};
}

template <size_t N>
constexpr nqr_menu_setting choice(const char* cvar, const char* label,
                                  const char* const (&choices)[N]) {
    return {sizeof(nqr_menu_setting),
            cvar,
            label,
            NQR_MENU_CHOICE,
            0,
            float(N - 1),
            1,
            choices,
            uint32_t(N)};
}

}  // namespace menu_line

}  // namespace nq::npr
