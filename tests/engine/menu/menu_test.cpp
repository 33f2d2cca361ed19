// The menu's rules (menu/menu.h) against a real HostCore and a scripted engine: which keys lead
// where, what each item changes (cvars stepped on Quake's grids, computed here) and which
// commands it queues; the style page built from a plugin's ABI 1.3 settings table and the
// checks on that table; and the layout (menu/menu_drawing.h) against pictures decoded straight
// from LibreQuake's gfx/*.lmp.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "fs/vfs.h"
#include "host/host_core.h"
#include "support/hud_test_support.h"
#include "menu/menu.h"
#include "menu/menu_drawing.h"
#include "plugin/style_settings.h"
#include "technical/technical_cvars.h"

namespace nq {
namespace {

using namespace test;

class FakeServices : public MenuServices {
  public:
    std::vector<std::string> style_names{"classic", "technical"};
    std::string active = "classic";
    std::vector<StyleSetting> settings;
    std::map<int, std::string> saves;
    bool running = false;

    std::vector<std::string> styles() const override { return style_names; }
    std::string active_style() const override { return active; }
    std::vector<StyleSetting> style_settings() const override { return settings; }
    std::string save_comment(int slot) const override {
        auto it = saves.find(slot);
        return it == saves.end() ? std::string() : it->second;
    }
    bool game_running() const override { return running; }
};

class MenuRules : public ::testing::Test {
  protected:
    void SetUp() override {
        for (auto [name, value] :
             std::vector<std::pair<const char*, const char*>>{{"viewsize", "100"},
                                                              {"gamma", "1"},
                                                              {"sensitivity", "3"},
                                                              {"fov", "90"},
                                                              {"cl_run", "1"},
                                                              {"m_pitch", "0.022"},
                                                              {"freelook", "1"}}) {
            host.cvars().register_cvar({name, value, 0, "", {}, {}});
        }
        // Commands the menu queues are recorded, not run.
        for (const char* name : {"map", "load", "save", "r_plugin", "quit", "toggleconsole",
                                 "deathmatch", "coop", "exec"}) {
            host.commands().add_command(name, [this, name](const CommandArgs& a) {
                std::string line = name;
                for (size_t i = 1; i < a.argc(); ++i) line += " " + a.argv(i);
                ran.push_back(line);
            });
        }
    }
    void press(std::initializer_list<const char*> keys) {
        for (const char* key : keys) menu.key_down(key);
        host.commands().execute();
    }
    float cvar(const char* name) { return host.cvars().find(name)->value(); }
    int row_of(const std::string& label) {
        for (size_t i = 0; i < menu.rows().size(); ++i) {
            if (menu.rows()[i].label == label) return int(i);
        }
        return -1;
    }
    void go_to_row(const std::string& label) {
        const int row = row_of(label);
        ASSERT_GE(row, 0) << label;
        while (menu.cursor() != row) menu.key_down("DOWNARROW");
    }

    HostCore host;
    FakeServices services;
    Menu menu{host, services};
    std::vector<std::string> ran;
};

TEST_F(MenuRules, ToggleMenuAndEscapeWalkTheScreensAsQuake) {
    EXPECT_FALSE(menu.active());
    host.commands().add_text("togglemenu\n");
    host.commands().execute();
    EXPECT_EQ(menu.screen(), MenuScreen::Main);
    press({"DOWNARROW", "DOWNARROW", "ENTER"});  // Single Player, Multiplayer, Options
    EXPECT_EQ(menu.screen(), MenuScreen::Options);
    host.commands().add_text("togglemenu\n");  // from a sub-menu: back to the main menu
    host.commands().execute();
    EXPECT_EQ(menu.screen(), MenuScreen::Main);
    EXPECT_EQ(menu.cursor(), 0);
    press({"UPARROW"});  // wraps to Quit
    EXPECT_EQ(menu.cursor(), 4);
    press({"ENTER"});
    EXPECT_EQ(menu.screen(), MenuScreen::Quit);
    press({"n"});
    EXPECT_EQ(menu.screen(), MenuScreen::Main);
    press({"ESCAPE"});
    EXPECT_FALSE(menu.active());
    menu.open(MenuScreen::Quit);
    press({"y"});
    EXPECT_EQ(ran, std::vector<std::string>{"quit"});
}

TEST_F(MenuRules, MultiplayerIsANoticeNotAScreen) {
    menu.open(MenuScreen::Main);
    press({"MWHEELDOWN", "MOUSE1"});
    EXPECT_EQ(menu.screen(), MenuScreen::Main);
    EXPECT_FALSE(menu.notice().empty());
    press({"DOWNARROW"});
    EXPECT_TRUE(menu.notice().empty());
}

TEST_F(MenuRules, NewGameStartsQuakesFirstMapAndCloses) {
    menu.open(MenuScreen::SinglePlayer);
    press({"ENTER"});
    EXPECT_FALSE(menu.active());
    EXPECT_EQ(ran, (std::vector<std::string>{"deathmatch 0", "coop 0", "map start"}));
}

TEST_F(MenuRules, OptionsListOnlyWhatTheEngineHas) {
    menu.open(MenuScreen::Options);
    EXPECT_EQ(row_of("Sound volume"), -1);  // no sound system registered `volume`
    host.cvars().register_cvar({"volume", "0.7", 0, "", 0.0f, 1.0f});
    menu.open(MenuScreen::Options);
    const int row = row_of("Sound volume");
    ASSERT_GE(row, 0);
    ASSERT_TRUE(menu.rows()[size_t(row)].slider);
    EXPECT_NEAR(*menu.rows()[size_t(row)].slider, 0.7f, 1e-5f);
}

TEST_F(MenuRules, OptionSlidersStepOnQuakesGridsAndStopAtTheEnds) {
    menu.open(MenuScreen::Options);
    go_to_row("Screen size");
    press({"RIGHTARROW"});
    EXPECT_EQ(cvar("viewsize"), 110.0f);
    press({"RIGHTARROW", "RIGHTARROW", "RIGHTARROW"});
    EXPECT_EQ(cvar("viewsize"), 120.0f);  // Quake's largest
    ASSERT_TRUE(menu.rows()[size_t(menu.cursor())].slider);
    EXPECT_EQ(*menu.rows()[size_t(menu.cursor())].slider, 1.0f);

    go_to_row("Brightness");  // right is brighter: gamma goes down by 0.05 from 1
    press({"RIGHTARROW", "RIGHTARROW"});
    EXPECT_NEAR(cvar("gamma"), 0.9f, 1e-5f);
    EXPECT_NEAR(*menu.rows()[size_t(menu.cursor())].slider, (1 - 0.9f) / 0.5f, 1e-5f);

    go_to_row("Mouse speed");
    press({"LEFTARROW"});
    EXPECT_EQ(cvar("sensitivity"), 2.5f);
    go_to_row("Field of view");
    press({"ENTER"});  // ENTER steps like the right arrow
    EXPECT_EQ(cvar("fov"), 95.0f);
}

TEST_F(MenuRules, TogglesFlipAndInvertMouseNegatesThePitchScale) {
    menu.open(MenuScreen::Options);
    go_to_row("Always run");
    press({"ENTER"});
    EXPECT_EQ(cvar("cl_run"), 0.0f);
    EXPECT_EQ(menu.rows()[size_t(menu.cursor())].value, "off");
    go_to_row("Invert mouse");
    EXPECT_EQ(menu.rows()[size_t(menu.cursor())].value, "off");
    press({"RIGHTARROW"});
    EXPECT_NEAR(cvar("m_pitch"), -0.022f, 1e-6f);
    EXPECT_EQ(menu.rows()[size_t(menu.cursor())].value, "on");
    press({"LEFTARROW"});
    EXPECT_NEAR(cvar("m_pitch"), 0.022f, 1e-6f);
}

// The engine-wide obscurance (every style has it) is switched on the Options page itself.
TEST_F(MenuRules, ObscuranceTogglesAreOnTheOptionsPageWhenTheEngineHasThem) {
    menu.open(MenuScreen::Options);
    EXPECT_EQ(row_of("Obscurance"), -1);  // no vo_enable registered yet
    host.cvars().register_cvar({"vo_enable", "0", 0, "", 0.0f, 1.0f});
    host.cvars().register_cvar({"vo_half", "0", 0, "", 0.0f, 1.0f});
    menu.open(MenuScreen::Options);
    go_to_row("Obscurance");
    EXPECT_EQ(menu.rows()[size_t(menu.cursor())].value, "off");
    press({"ENTER"});
    EXPECT_EQ(cvar("vo_enable"), 1.0f);
    EXPECT_EQ(menu.rows()[size_t(menu.cursor())].value, "on");
    go_to_row("Obscurance res");
    EXPECT_EQ(menu.rows()[size_t(menu.cursor())].value, "full");
    press({"RIGHTARROW"});
    EXPECT_EQ(cvar("vo_half"), 1.0f);
    EXPECT_EQ(menu.rows()[size_t(menu.cursor())].value, "half");
    press({"LEFTARROW"});
    EXPECT_EQ(cvar("vo_half"), 0.0f);
}

TEST_F(MenuRules, RendererStyleCyclesThePluginsThroughRPlugin) {
    services.style_names = {"classic", "illustrative", "technical"};
    menu.open(MenuScreen::Options);
    go_to_row("Renderer style");
    EXPECT_EQ(menu.rows()[size_t(menu.cursor())].value, "classic");
    press({"RIGHTARROW"});
    EXPECT_EQ(ran.back(), "r_plugin illustrative");
    EXPECT_EQ(menu.rows()[size_t(menu.cursor())].value, "illustrative");
    services.active = "illustrative";  // the swap happened
    press({"RIGHTARROW"});
    EXPECT_EQ(ran.back(), "r_plugin technical");
    services.active = "technical";
    press({"RIGHTARROW"});  // wraps
    EXPECT_EQ(ran.back(), "r_plugin classic");
    services.active = "classic";
    press({"LEFTARROW"});
    EXPECT_EQ(ran.back(), "r_plugin technical");
}

TEST_F(MenuRules, StylePageChangesTheStylesOwnCvars) {
    host.cvars().register_cvar({"tech_silhouettes", "1", 0, "", {}, {}});
    host.cvars().register_cvar({"tech_silhouette_width", "2", 0, "", {}, {}});
    host.cvars().register_cvar({"tech_shading", "3", 0, "", {}, {}});
    services.settings = {
        {"tech_silhouettes", "Silhouettes", StyleSettingKind::Toggle, 0, 1, 1, {}},
        {"tech_silhouette_width", "Silhouette width", StyleSettingKind::Range, 0.5f, 6, 0.5f, {}},
        {"tech_shading",
         "Shading",
         StyleSettingKind::Choice,
         0,
         3,
         1,
         {"classic", "gooch", "metal", "object id"}},
        {"not_registered", "Ghost", StyleSettingKind::Toggle, 0, 1, 1, {}},
    };
    menu.open(MenuScreen::Options);
    go_to_row("Style settings...");
    press({"ENTER"});
    ASSERT_EQ(menu.screen(), MenuScreen::Style);
    ASSERT_EQ(menu.rows().size(), 4u);
    EXPECT_EQ(menu.rows()[2].value, "object id");
    EXPECT_FALSE(menu.rows()[3].enabled);  // its cvar does not exist

    press({"ENTER"});
    EXPECT_EQ(cvar("tech_silhouettes"), 0.0f);
    press({"DOWNARROW", "RIGHTARROW", "RIGHTARROW"});
    EXPECT_EQ(cvar("tech_silhouette_width"), 3.0f);
    for (int i = 0; i < 20; ++i) press({"LEFTARROW"});
    EXPECT_EQ(cvar("tech_silhouette_width"), 0.5f);
    press({"DOWNARROW", "RIGHTARROW"});  // the last choice wraps to the first
    EXPECT_EQ(cvar("tech_shading"), 0.0f);
    EXPECT_EQ(menu.rows()[2].value, "classic");
    press({"DOWNARROW"});  // the disabled row is skipped: back to the first
    EXPECT_EQ(menu.cursor(), 0);
    press({"ESCAPE"});
    EXPECT_EQ(menu.screen(), MenuScreen::Options);
}

TEST_F(MenuRules, StylePageWithoutSettingsSaysSo) {
    menu.open(MenuScreen::Style);
    ASSERT_EQ(menu.rows().size(), 1u);
    EXPECT_FALSE(menu.rows()[0].enabled);
    EXPECT_NE(menu.rows()[0].label.find("classic"), std::string::npos);
    press({"ENTER", "RIGHTARROW"});  // nothing to change, nothing breaks
    EXPECT_TRUE(ran.empty());
}

TEST_F(MenuRules, LoadOffersOnlyUsedSlotsAndSaveNeedsAGame) {
    services.saves = {{3, "The Test Level         kills:  1/ 20"}, {7, "start"}};
    menu.open(MenuScreen::Load);
    ASSERT_EQ(menu.rows().size(), size_t(kSaveSlots));
    EXPECT_EQ(menu.rows()[3].label, services.saves[3]);
    EXPECT_FALSE(menu.rows()[0].enabled);
    EXPECT_EQ(menu.cursor(), 3);  // the first used slot; empty slots are skipped
    press({"DOWNARROW"});
    EXPECT_EQ(menu.cursor(), 7);
    press({"DOWNARROW"});
    EXPECT_EQ(menu.cursor(), 3);  // wraps
    press({"UPARROW"});
    EXPECT_EQ(menu.cursor(), 7);
    press({"ENTER"});
    EXPECT_FALSE(menu.active());
    EXPECT_EQ(ran, std::vector<std::string>{"load s7"});

    host.commands().add_text("menu_save\n");  // Quake: no save menu without a game
    host.commands().execute();
    EXPECT_FALSE(menu.active());
    services.running = true;
    host.commands().add_text("menu_save\n");
    host.commands().execute();
    ASSERT_EQ(menu.screen(), MenuScreen::Save);
    EXPECT_TRUE(menu.rows()[0].enabled);  // any slot can be written
    press({"ENTER"});
    EXPECT_EQ(ran.back(), "save s0");
}

TEST_F(MenuRules, HelpPagesTurnBothWays) {
    menu.set_help_pages(6);
    menu.open(MenuScreen::Help);
    press({"LEFTARROW"});
    EXPECT_EQ(menu.help_page(), 5);
    press({"ENTER", "RIGHTARROW"});
    EXPECT_EQ(menu.help_page(), 1);
}

TEST_F(MenuRules, RemovesItsCommandsWhenItGoes) {
    {
        HostCore other;
        FakeServices fake;
        {
            Menu temporary(other, fake);
            EXPECT_TRUE(other.commands().has_command("togglemenu"));
        }
        EXPECT_FALSE(other.commands().has_command("togglemenu"));
        EXPECT_FALSE(other.commands().has_command("menu_options"));
    }
}

// ---- the ABI 1.3 settings table

nqr_renderer table_with(const nqr_menu_setting* settings, uint32_t count) {
    nqr_renderer table{};
    table.size = sizeof(nqr_renderer);
    table.menu_settings = settings;
    table.num_menu_settings = count;
    return table;
}

TEST(StyleSettingsTable, GoodEntriesAreCopiedAndBadOnesDroppedWithAReason) {
    const char* const choices[] = {"a", "b", "c"};
    const char* const broken_choices[] = {"a", nullptr};
    const uint32_t s = sizeof(nqr_menu_setting);
    const nqr_menu_setting entries[] = {
        {s, "t_toggle", "Toggle", NQR_MENU_TOGGLE, 5, 9, 3, nullptr, 0},
        {s, "t_range", "Range", NQR_MENU_RANGE, 1, 4, 0.5f, nullptr, 0},
        {s, "t_choice", "Choice", NQR_MENU_CHOICE, 0, 0, 0, choices, 3},
        {s, "t_nolabel", nullptr, NQR_MENU_TOGGLE, 0, 1, 1, nullptr, 0},
        {s, "t_backwards", "Backwards", NQR_MENU_RANGE, 4, 1, 0.5f, nullptr, 0},
        {s, "t_nan", "NaN", NQR_MENU_RANGE, 0, NAN, 1, nullptr, 0},
        {s, "t_kind", "Kind", 7, 0, 1, 1, nullptr, 0},
        {s, "t_holes", "Holes", NQR_MENU_CHOICE, 0, 0, 0, broken_choices, 2},
    };
    const StyleSettings read = read_style_settings(table_with(entries, 8));
    ASSERT_EQ(read.settings.size(), 3u);
    EXPECT_EQ(read.dropped.size(), 5u);
    EXPECT_EQ(read.settings[0].kind, StyleSettingKind::Toggle);
    EXPECT_EQ(read.settings[0].min, 0.0f);  // a toggle is 0..1 whatever the table says
    EXPECT_EQ(read.settings[0].max, 1.0f);
    EXPECT_EQ(read.settings[1].step, 0.5f);
    EXPECT_EQ(read.settings[2].choices, (std::vector<std::string>{"a", "b", "c"}));
    EXPECT_EQ(read.settings[2].max, 2.0f);
}

TEST(StyleSettingsTable, OlderTablesAndImplausibleStridesGiveNoSettings) {
    const nqr_menu_setting entry = {
        sizeof(nqr_menu_setting), "x", "X", NQR_MENU_TOGGLE, 0, 1, 1, nullptr, 0};
    nqr_renderer old = table_with(&entry, 1);
    old.size = offsetof(nqr_renderer, menu_settings);  // an ABI 1.2 plugin
    EXPECT_TRUE(read_style_settings(old).settings.empty());

    nqr_menu_setting short_entry = entry;
    short_entry.size = 8;
    const StyleSettings read = read_style_settings(table_with(&short_entry, 1));
    EXPECT_TRUE(read.settings.empty());
    EXPECT_EQ(read.dropped.size(), 1u);

    const StyleSettings many = read_style_settings(table_with(&entry, 1));
    EXPECT_EQ(many.settings.size(), 1u);
}

TEST(StyleSettingsTable, TheTechnicalStylesEntriesAreAllShownAndNameItsCvars) {
    const auto entries = npr::technical::technical_menu_settings();
    const StyleSettings read =
        read_style_settings(table_with(entries.data(), uint32_t(entries.size())));
    EXPECT_TRUE(read.dropped.empty()) << read.dropped.front();
    ASSERT_EQ(read.settings.size(), entries.size());
    for (const StyleSetting& setting : read.settings) {
        bool bound = false;
        for (const auto& binding : npr::technical::technical_cvar_bindings()) {
            if (setting.cvar == binding.name) {
                bound = true;
                // The cvar's default is a value the menu can show.
                const float value = std::strtof(binding.default_value, nullptr);
                EXPECT_GE(value, setting.min) << setting.cvar;
                EXPECT_LE(value, setting.max) << setting.cvar;
            }
        }
        EXPECT_TRUE(bound) << setting.cvar << " is not a technical cvar";
    }
}

// ---- layout

class MenuLayout : public MenuRules {
  protected:
    static Pic lmp(const std::string& name) {
        auto bytes = read_file(lq1_dir() + "/gfx/" + name + ".lmp");
        if (!bytes) throw std::runtime_error(bytes.error().to_string());
        auto pic = parse_qpic(*bytes, name);
        if (!pic) throw std::runtime_error(pic.error().to_string());
        return std::move(*pic);
    }
    std::vector<EmittedQuad> quads(const HudPictures& pictures, const HudScreen& screen,
                                   double real_time = 0) {
        return emitted_quads(
            [&](QuadBatch& batch) { build_menu(menu, pictures, screen, real_time, batch); });
    }
    static bool has_quad(const std::vector<EmittedQuad>& quads, float x0, float y0, float x1,
                         float y1) {
        for (const EmittedQuad& q : quads) {
            if (q.x0 == x0 && q.y0 == y0 && q.x1 == x1 && q.y1 == y1) return true;
        }
        return false;
    }
};

TEST_F(MenuLayout, MainMenuPicturesLandWhereQuakePutsThem) {
    HudTestData data;
    auto vfs = Vfs::mount(VfsConfig::for_game(data_root(), "lq1"));
    ASSERT_TRUE(vfs) << vfs.error().message;
    const HudPictures pictures = HudPictures::load(data.wad, data.palette, &*vfs);
    const Pic items = lmp("mainmenu"), plaque = lmp("qplaque"), title = lmp("ttl_main"),
              dot = lmp("menudot1");
    // 640x480, scr_menuscale 2: the 320x200 canvas doubled, centred: top (480 - 400) / 2.
    const HudScreen screen{640, 480, 2};
    const float left = 0, top = 40, scale = 2;
    menu.open(MenuScreen::Main);
    menu.key_down("DOWNARROW");
    menu.key_down("DOWNARROW");  // Options
    const std::vector<EmittedQuad> q = quads(pictures, screen);
    ASSERT_FALSE(q.empty());
    EXPECT_EQ(q[0].x1, 640.0f);  // the faded screen first
    EXPECT_EQ(q[0].colour.a, 127);
    EXPECT_TRUE(has_quad(q, left + 72 * scale, top + 32 * scale, left + (72 + items.width) * scale,
                         top + (32 + items.height) * scale));
    EXPECT_TRUE(has_quad(q, left + 16 * scale, top + 4 * scale, left + (16 + plaque.width) * scale,
                         top + (4 + plaque.height) * scale));
    const float title_x = std::floor((320 - float(title.width)) / 2);
    EXPECT_TRUE(has_quad(q, left + title_x * scale, top + 4 * scale,
                         left + (title_x + title.width) * scale, top + (4 + title.height) * scale));
    const float dot_y = 32 + 20 * 2;  // third row
    EXPECT_TRUE(has_quad(q, left + 54 * scale, top + dot_y * scale, left + (54 + dot.width) * scale,
                         top + (dot_y + dot.height) * scale));

    // The pointer over a row's middle picks that row.
    for (int row = 0; row < 5; ++row) {
        EXPECT_EQ(menu_row_at(menu, screen, 200, top + (32 + 20 * row + 10) * scale), row);
    }
    EXPECT_EQ(menu_row_at(menu, screen, 200, top + 20 * scale), -1);
}

TEST_F(MenuLayout, MissingPicturesFallBackToTheConsoleFont) {
    HudTestData data;  // pictures from gfx.wad only: no gfx/*.lmp
    const HudScreen screen{320, 200, 1};
    menu.open(MenuScreen::Main);
    const std::vector<EmittedQuad> q = quads(data.pictures, screen);
    // "Single Player" in 8x8 glyphs from (72, 32 + 6): one glyph quad per non-space letter.
    const std::string label = "Single Player";
    for (size_t i = 0; i < label.size(); ++i) {
        if (label[i] == ' ') continue;
        EXPECT_TRUE(has_quad(q, 72 + 8 * float(i), 38, 80 + 8 * float(i), 46)) << i;
    }
}

TEST_F(MenuLayout, OptionLabelsEndAtTheCursorColumnAndSlidersStartAt220) {
    HudTestData data;
    const HudScreen screen{320, 200, 1};
    menu.open(MenuScreen::Options);
    const std::vector<EmittedQuad> q = quads(data.pictures, screen);
    const int row = row_of("Screen size");
    const float y = 32 + 8 * float(row);
    EXPECT_TRUE(has_quad(q, 192 - 8, y, 192, y + 8));  // the label's last letter
    EXPECT_TRUE(has_quad(q, 212, y, 220, y + 8));      // the slider's left end
    // viewsize 100 of 30..120: the handle at 220 + 9 * 8 * (70 / 90), rounded.
    const float handle = 220 + std::round(9 * 8 * (70.0f / 90.0f));
    EXPECT_TRUE(has_quad(q, handle, y, handle + 8, y + 8));
}

}  // namespace
}  // namespace nq
