// The one plugin shell (nprlib/abi/plugin_shell.h) with made-up styles: the table it fills
// (names, every hook, begin_frame only when the style has something to do then, the menu
// page), the version check, one order for every style (cvars registered and read before the
// renderer's init, read again at each begin_frame before the renderer's own), and instances
// as the transactional swap needs them (hooks reach the newest, shutdown retires the oldest).
#include <gtest/gtest.h>

#include <algorithm>

#include <string>
#include <vector>

#include "abi/plugin_shell.h"

namespace nq::npr {
namespace {

std::vector<std::string> g_events;  // what the made-up styles saw, in order

struct Settings {
    int reads = 0;
};

struct FakeCvars {
    void register_all(const nqr_engine&) { g_events.push_back("cvars registered"); }
    void update(Settings& s) {
        ++s.reads;
        g_events.push_back("cvars read");
    }
};

template <bool kInitSucceeds>
struct FakeRenderer {
    static inline int next_id = 0;
    int id = ++next_id;
    Settings settings;
    bool init(const nqr_engine*, std::string* error) {
        g_events.push_back("init " + std::to_string(id) + " after " +
                           std::to_string(settings.reads) + " cvar reads");
        if (!kInitSucceeds) *error = "no";
        return kInitSucceeds;
    }
    ~FakeRenderer() { g_events.push_back("gone " + std::to_string(id)); }
    void register_model(const nqr_model*) { g_events.push_back("model " + std::to_string(id)); }
    void release_model(nqr_model_id) {}
    void begin_frame() { g_events.push_back("renderer begins " + std::to_string(id)); }
    void draw_world(const nqr_frame*) { g_events.push_back("world " + std::to_string(id)); }
    void draw_brush_entities(const nqr_frame*) {}
    void draw_alias_entities(const nqr_frame*) {}
    void draw_sprite_entities(const nqr_frame*) {}
    void draw_particles(const nqr_frame*) {}
};

struct PlainRenderer {
    Settings settings;
    bool init(const nqr_engine*, std::string*) { return true; }
    void register_model(const nqr_model*) {}
    void release_model(nqr_model_id) {}
    void draw_world(const nqr_frame*) {}
    void draw_brush_entities(const nqr_frame*) {}
    void draw_alias_entities(const nqr_frame*) {}
    void draw_sprite_entities(const nqr_frame*) {}
    void draw_particles(const nqr_frame*) {}
};

const nqr_menu_setting kMenu[1] = {
    {sizeof(nqr_menu_setting), "fake_cvar", "Fake", NQR_MENU_TOGGLE, 0, 1, 1, nullptr, 0}};

struct FakeStyle {
    using Renderer = FakeRenderer<true>;
    using Cvars = FakeCvars;
    static constexpr const char* kName = "fake";
    static constexpr const char* kDescription = "a made-up style";
    static std::span<const nqr_menu_setting> menu_settings() { return kMenu; }
};

struct PlainStyle {
    using Renderer = PlainRenderer;
    using Cvars = NoStyleCvars;
    static constexpr const char* kName = "plain";
    static constexpr const char* kDescription = "no cvars, no begin_frame";
    static std::span<const nqr_menu_setting> menu_settings() { return {}; }
};

struct FailingStyle {
    using Renderer = FakeRenderer<false>;
    using Cvars = FakeCvars;
    static constexpr const char* kName = "failing";
    static constexpr const char* kDescription = "init fails";
    static std::span<const nqr_menu_setting> menu_settings() { return {}; }
};

nqr_engine engine_table() {
    nqr_engine engine{};
    engine.size = sizeof(nqr_engine);
    engine.abi_version = NQR_ABI_VERSION;
    return engine;
}

TEST(PluginShell, FillsTheTableFromTheStyle) {
    const nqr_engine engine = engine_table();
    const nqr_renderer* table = PluginShell<FakeStyle>::table(NQR_ABI_VERSION, &engine);
    ASSERT_NE(table, nullptr);
    EXPECT_EQ(table->size, sizeof(nqr_renderer));
    EXPECT_EQ(table->abi_version, NQR_ABI_VERSION);
    EXPECT_STREQ(table->name, "fake");
    EXPECT_STREQ(table->description, "a made-up style");
    for (const void* hook :
         {(const void*)table->init, (const void*)table->shutdown,
          (const void*)table->register_model, (const void*)table->release_model,
          (const void*)table->begin_frame, (const void*)table->draw_world,
          (const void*)table->draw_brush_entities, (const void*)table->draw_alias_entities,
          (const void*)table->draw_sprite_entities, (const void*)table->draw_particles}) {
        EXPECT_NE(hook, nullptr);
    }
    EXPECT_EQ(table->post_process, nullptr);
    EXPECT_EQ(table->end_frame, nullptr);
    ASSERT_EQ(table->num_menu_settings, 1u);
    EXPECT_STREQ(table->menu_settings[0].cvar, "fake_cvar");

    const nqr_renderer* plain = PluginShell<PlainStyle>::table(NQR_ABI_VERSION, &engine);
    ASSERT_NE(plain, nullptr);
    EXPECT_EQ(plain->begin_frame, nullptr) << "nothing to do at a frame's start";
    EXPECT_EQ(plain->menu_settings, nullptr);
    EXPECT_EQ(plain->num_menu_settings, 0u);
}

TEST(PluginShell, RefusesAnotherMajorVersionOrAShortEngineTable) {
    nqr_engine engine = engine_table();
    EXPECT_EQ(PluginShell<FakeStyle>::table((NQR_ABI_VERSION_MAJOR + 1) << 16, &engine), nullptr);
    EXPECT_EQ(PluginShell<FakeStyle>::table(NQR_ABI_VERSION, nullptr), nullptr);
    engine.size = sizeof(nqr_engine) - 8;
    EXPECT_EQ(PluginShell<FakeStyle>::table(NQR_ABI_VERSION, &engine), nullptr);
}

TEST(PluginShell, CvarsComeFirstAndEachFrameReadsThemBeforeTheRendererBegins) {
    g_events.clear();
    const nqr_engine engine = engine_table();
    const nqr_renderer* table = PluginShell<FakeStyle>::table(NQR_ABI_VERSION, &engine);
    void* self = table->init(&engine);
    ASSERT_NE(self, nullptr);
    const int id = FakeRenderer<true>::next_id;
    nqr_frame frame{};
    table->begin_frame(self, &frame);
    table->shutdown(self);
    const std::string n = std::to_string(id);
    EXPECT_EQ(g_events, (std::vector<std::string>{"cvars registered", "cvars read",
                                                  "init " + n + " after 1 cvar reads", "cvars read",
                                                  "renderer begins " + n, "gone " + n}));
}

// `r_plugin` naming the active style: the engine inits the new instance before the old one
// shuts down, both from one library image; each hook reaches the instance it is given.
TEST(PluginShell, TwoInstancesOfOneStyleLiveSideBySide) {
    g_events.clear();
    const nqr_engine engine = engine_table();
    const nqr_renderer* table = PluginShell<FakeStyle>::table(NQR_ABI_VERSION, &engine);
    void* old_self = table->init(&engine);
    ASSERT_NE(old_self, nullptr);
    const int old_id = FakeRenderer<true>::next_id;
    void* new_self = table->init(&engine);
    ASSERT_NE(new_self, nullptr);
    ASSERT_NE(new_self, old_self);
    const int new_id = FakeRenderer<true>::next_id;
    nqr_frame frame{};
    table->draw_world(old_self, &frame);
    table->shutdown(old_self);
    table->draw_world(new_self, &frame);
    nqr_model model{};
    table->register_model(new_self, &model);
    const std::vector<std::string> tail(g_events.end() - 4, g_events.end());
    EXPECT_EQ(tail, (std::vector<std::string>{
                        "world " + std::to_string(old_id), "gone " + std::to_string(old_id),
                        "world " + std::to_string(new_id), "model " + std::to_string(new_id)}));
    table->shutdown(new_self);
    EXPECT_EQ(g_events.back(), "gone " + std::to_string(new_id));
}

TEST(PluginShell, AFailedInitKeepsNoInstance) {
    g_events.clear();
    const nqr_engine engine = engine_table();
    const nqr_renderer* table = PluginShell<FailingStyle>::table(NQR_ABI_VERSION, &engine);
    EXPECT_EQ(table->init(&engine), nullptr);
    const std::string n = std::to_string(FakeRenderer<false>::next_id);
    EXPECT_EQ(g_events.back(), "gone " + n) << "the failed instance is not kept";
}

}  // namespace
}  // namespace nq::npr
