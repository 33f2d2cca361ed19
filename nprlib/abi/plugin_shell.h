// The one shell every C++ renderer plugin is built from: a style names its renderer class, its
// cvar table (if any), its name, description and menu page, and NQR_DEFINE_PLUGIN(Style) gives
// the library its nqr_get_renderer with a function table filled by designated initialisers.
//
//   struct TechnicalStyle {
//       using Renderer = TechnicalRenderer;  // init(engine, &error), register_model, ...
//       using Cvars = TechnicalCvars;        // register_all(engine), update(renderer.settings)
//       static constexpr const char* kName = "technical";
//       static constexpr const char* kDescription = "...";
//       static std::span<const nqr_menu_setting> menu_settings();
//   };
//   NQR_DEFINE_PLUGIN(TechnicalStyle)
//
// One order for every style: cvars are registered and read before the renderer's init (a style
// chooses resources from them there), and read again at the start of every frame. A renderer
// with a begin_frame() gets it called after that. Each init makes a new instance (renderer and
// cvars), so one library image can run two at once during a swap; shutdown deletes it.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <type_traits>

#include "abi/plugin_entry.h"
#include "nqr_renderer.h"

namespace nq::npr {

// For a style without cvars of its own.
struct NoStyleCvars {
    void register_all(const nqr_engine&) {}
    template <class Settings>
    void update(Settings&) {}
};

template <class Style>
class PluginShell {
    using Renderer = typename Style::Renderer;
    using Cvars = typename Style::Cvars;
    // The plugin's instance: what init returns and every hook gets back as `self`.
    struct Instance {
        Renderer renderer;
        Cvars cvars;
    };

    static constexpr bool kHasCvars = !std::is_same_v<Cvars, NoStyleCvars>;
    static constexpr bool kRendererBegins = requires(Renderer & r) { r.begin_frame(); };

  public:
    static const nqr_renderer* table(uint32_t engine_abi_version, const nqr_engine* engine) {
        return engine_abi_compatible(engine_abi_version, engine) ? &kTable : nullptr;
    }

  private:
    static Instance& instance(void* self) { return *static_cast<Instance*>(self); }
    static Renderer& renderer(void* self) { return instance(self).renderer; }

    static void* init(const nqr_engine* engine) {
        auto fresh = std::make_unique<Instance>();
        if constexpr (kHasCvars) {
            fresh->cvars.register_all(*engine);
            fresh->cvars.update(fresh->renderer.settings);
        }
        std::string error;
        if (!fresh->renderer.init(engine, &error)) return nullptr;  // init() logged why
        return fresh.release();
    }
    static void shutdown(void* self) { delete static_cast<Instance*>(self); }

    static void register_model(void* self, const nqr_model* m) { renderer(self).register_model(m); }
    static void release_model(void* self, nqr_model_id id) { renderer(self).release_model(id); }
    static void begin_frame(void* self, const nqr_frame*) {
        Instance& i = instance(self);
        if constexpr (kHasCvars) i.cvars.update(i.renderer.settings);
        if constexpr (kRendererBegins) i.renderer.begin_frame();
    }
    static void draw_world(void* self, const nqr_frame* f) { renderer(self).draw_world(f); }
    static void draw_brush(void* self, const nqr_frame* f) {
        renderer(self).draw_brush_entities(f);
    }
    static void draw_alias(void* self, const nqr_frame* f) {
        renderer(self).draw_alias_entities(f);
    }
    static void draw_sprites(void* self, const nqr_frame* f) {
        renderer(self).draw_sprite_entities(f);
    }
    static void draw_particles(void* self, const nqr_frame* f) { renderer(self).draw_particles(f); }

    static inline const nqr_renderer kTable = {
        .size = sizeof(nqr_renderer),
        .abi_version = NQR_ABI_VERSION,
        .name = Style::kName,
        .description = Style::kDescription,
        .wants = 0,
        .init = &init,
        .shutdown = &shutdown,
        .register_model = &register_model,
        .release_model = &release_model,
        .begin_frame = kHasCvars || kRendererBegins ? &begin_frame : nullptr,
        .draw_world = &draw_world,
        .draw_brush_entities = &draw_brush,
        .draw_alias_entities = &draw_alias,
        .draw_sprite_entities = &draw_sprites,
        .draw_particles = &draw_particles,
        .post_process = nullptr,
        .end_frame = nullptr,
        .menu_settings = Style::menu_settings().empty() ? nullptr : Style::menu_settings().data(),
        .num_menu_settings = static_cast<uint32_t>(Style::menu_settings().size()),
    };
};

}  // namespace nq::npr

// The library's entry point for `Style` (at namespace scope, once per plugin).
#define NQR_DEFINE_PLUGIN(Style)                                                            \
    extern "C" NQR_EXPORT const nqr_renderer* nqr_get_renderer(uint32_t engine_abi_version, \
                                                               const nqr_engine* engine) {  \
        return ::nq::npr::PluginShell<Style>::table(engine_abi_version, engine);            \
    }
