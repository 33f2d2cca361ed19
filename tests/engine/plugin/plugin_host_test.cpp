#include <gtest/gtest.h>

#include <dlfcn.h>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "plugin/plugin_host.h"
#include "support/build_paths.h"
#include "support/null_engine_services.h"

namespace nq {
namespace {

// Mirrors probe_counters in tests/plugins/test_plugin.c.
struct ProbeCounters {
    int inits, shutdowns, models_registered, models_released, frames;
    const nqr_cvar* cvar;
};

// Records what plugins asked of the engine.
class FakeServices : public test::NullEngineServices {
  public:
    void log(int, std::string_view text) override { logs.emplace_back(text); }
    const nqr_cvar* register_cvar(OwnerId, const char* name, const char* def, uint32_t,
                                  const char*) override {
        auto& c = cvars[name];
        if (!c.string) c = nqr_cvar{sizeof(nqr_cvar), std::stof(def), std::stoi(def), def, 0};
        return &c;
    }
    // Same-named commands stack up: during a swap the old and the new plugin both hold one,
    // and releasing the old owner must leave the new one's in place.
    bool register_command(OwnerId owner, const char* name, nqr_command_fn, void*,
                          const char*) override {
        commands[name].push_back(owner);
        return true;
    }
    void release_owner(OwnerId owner) override {
        for (auto& [name, owners] : commands) std::erase(owners, owner);
        std::erase_if(commands, [](const auto& kv) { return kv.second.empty(); });
        released.push_back(owner);
    }
    // Something to hand out: no plugin here draws, but one may look its GL functions up.
    void* gl_proc_address(const char*) override { return reinterpret_cast<void*>(&no_gl); }
    static void no_gl() {}
    const uint8_t* palette() override { return palette_bytes; }
    const uint8_t* colormap() override { return colormap_bytes; }

    std::vector<std::string> logs;
    std::map<std::string, nqr_cvar> cvars;
    std::map<std::string, std::vector<OwnerId>> commands;
    std::vector<OwnerId> released;
    uint8_t palette_bytes[768] = {};
    uint8_t colormap_bytes[64 * 256 + 256] = {};
};

ProbeCounters* probe_counters(const std::string& dir) {
    // The host loaded it RTLD_LOCAL; dlopen of the same path returns the same instance.
    void* h = dlopen((dir + "/nqr_test_probe.so").c_str(), RTLD_NOW | RTLD_NOLOAD);
    if (!h) return nullptr;
    auto fn = reinterpret_cast<ProbeCounters* (*)()>(dlsym(h, "nqr_test_counters"));
    dlclose(h);  // drops our extra reference only
    return fn ? fn() : nullptr;
}

nqr_model make_model(nqr_model_id id) {
    nqr_model m{};
    m.size = sizeof m;
    m.id = id;
    m.kind = NQR_MODEL_ALIAS;
    m.name = "progs/test.mdl";
    return m;
}

TEST(PluginHost, ListsPluginsInDirectory) {
    FakeServices services;
    PluginHost host(services, test::test_plugin_dir());
    std::vector<std::string> names;
    for (const auto& p : host.available()) names.push_back(p.name);
    std::vector<std::string> expected = {"legacy15",     "test_badabi", "test_failinit",
                                         "test_noentry", "test_post",   "test_probe",
                                         "test_refuse",  "test_small"};
    EXPECT_EQ(names, expected);
}

TEST(PluginHost, LoadsInitialisesAndRegistersModels) {
    FakeServices services;
    PluginHost host(services, test::test_plugin_dir());
    nqr_model a = make_model(1), b = make_model(2);
    host.register_model(&a);
    ASSERT_EQ(host.load("test_probe"), "");
    ProbeCounters* c = probe_counters(test::test_plugin_dir());
    ASSERT_NE(c, nullptr);
    EXPECT_EQ(c->inits, 1);
    EXPECT_EQ(c->models_registered, 1);  // the model loaded before the plugin
    host.register_model(&b);
    EXPECT_EQ(c->models_registered, 2);
    host.release_model(1);
    EXPECT_EQ(c->models_released, 1);
    EXPECT_EQ(host.active_name(), "probe");
    EXPECT_EQ(services.commands.count("probe_cmd"), 1u);
    ASSERT_NE(c->cvar, nullptr);
    EXPECT_EQ(c->cvar->integer, 7);
}

TEST(PluginHost, WrongAbiIsRefusedWithReasonAndKeepsCurrent) {
    FakeServices services;
    PluginHost host(services, test::test_plugin_dir());
    ASSERT_EQ(host.load("test_probe"), "");
    std::string why = host.load("test_badabi");
    EXPECT_NE(why.find("ABI version mismatch"), std::string::npos) << why;
    EXPECT_NE(why.find("0x00030000"), std::string::npos) << why;
    EXPECT_EQ(host.active_name(), "probe");
}

TEST(PluginHost, EveryKindOfBrokenPluginKeepsTheCurrentRenderer) {
    FakeServices services;
    PluginHost host(services, test::test_plugin_dir());
    ASSERT_EQ(host.load("test_probe"), "");
    const std::map<std::string, std::string> expected = {
        {"test_refuse", "refused"},
        {"test_failinit", "failed to initialise"},
        {"test_small", "table too small"},
        {"test_noentry", "no nqr_get_renderer symbol"},
        {"does_not_exist", "no renderer plugin"},
        {"../etc/passwd", "invalid plugin name"},
    };
    for (const auto& [name, text] : expected) {
        std::string why = host.load(name);
        EXPECT_NE(why.find(text), std::string::npos) << name << ": " << why;
        EXPECT_EQ(host.active_name(), "probe") << name;
    }
    // The failing init registered a command; it must be gone with the library.
    EXPECT_EQ(services.commands.count("probe_cmd"), 1u);  // the active probe's own
    EXPECT_EQ(host.load_count(), 1u);
}

TEST(PluginHost, LoadsTheRealNullPlugin) {
    FakeServices services;
    PluginHost host(services, test::plugin_dir());
    ASSERT_EQ(host.load("null"), "") << "the null plugin must build into bin/plugins";
    EXPECT_EQ(host.active_name(), "null");
    ASSERT_FALSE(services.logs.empty());
    EXPECT_NE(services.logs.back().find("null renderer"), std::string::npos);
}

TEST(PluginHost, FiftySwapsReleaseEverything) {
    FakeServices services;
    PluginHost host(services, test::test_plugin_dir());
    nqr_model a = make_model(1);
    host.register_model(&a);
    for (int i = 0; i < 50; ++i) ASSERT_EQ(host.load("test_probe"), "") << "swap " << i;
    ProbeCounters* c = probe_counters(test::test_plugin_dir());
    ASSERT_NE(c, nullptr);
    // Swapping to the same file reuses the loaded image (the old one is still open while the
    // new one initialises), so the counters accumulate: every replaced instance shut down.
    EXPECT_EQ(c->inits, 50);
    EXPECT_EQ(c->shutdowns, 49);
    EXPECT_EQ(c->models_registered, 50);
    EXPECT_EQ(services.released.size(), 49u);  // every replaced plugin's owner was released
    host.unload();
    EXPECT_EQ(probe_counters(test::test_plugin_dir()), nullptr) << "library still loaded";
}

// A plugin built for ABI 1.5 (tests/plugins/legacy_1_5_plugin.c, from the 1.5 header) loads
// through the adapter: its context-free services reach the host under its own owner, and swaps
// between it and a 2.0 plugin go both ways, each releasing what the other registered.
TEST(PluginHost, LoadsA15PluginAndSwapsWithA20One) {
    FakeServices services;
    PluginHost host(services, test::test_plugin_dir());
    nqr_model a = make_model(1);
    host.register_model(&a);
    ASSERT_EQ(host.load("test_probe"), "");
    ASSERT_EQ(host.load("legacy15"), "");
    EXPECT_EQ(host.active_name(), "legacy15");
    ASSERT_NE(host.active(), nullptr);
    EXPECT_EQ(NQR_ABI_MAJOR(host.active()->abi_version), 1u);
    EXPECT_NE(host.active_self(), nullptr);
    ASSERT_FALSE(services.logs.empty());
    EXPECT_EQ(services.logs.back(), "legacy15: a 1.5 plugin is running");
    ASSERT_EQ(services.cvars.count("legacy15_marker"), 1u);
    EXPECT_EQ(services.cvars["legacy15_marker"].integer, 6);
    ASSERT_EQ(services.commands.count("legacy15_report"), 1u);
    const OwnerId legacy_owner = services.commands["legacy15_report"].front();
    EXPECT_EQ(services.commands.count("probe_cmd"), 0u) << "the probe's command left with it";
    // 1.x hooks the plugin lacks stay NULL (the engine draws those parts), present ones wrap.
    EXPECT_EQ(host.active()->begin_frame, nullptr);
    EXPECT_NE(host.active()->draw_world, nullptr);
    EXPECT_NE(host.active()->draw_alias_entities, nullptr);

    ASSERT_EQ(host.load("test_probe"), "");
    EXPECT_EQ(services.commands.count("legacy15_report"), 0u);
    EXPECT_NE(std::find(services.released.begin(), services.released.end(), legacy_owner),
              services.released.end());
    ASSERT_EQ(host.load("legacy15"), "") << "and back again";
    EXPECT_EQ(host.active_name(), "legacy15");
}

}  // namespace
}  // namespace nq
