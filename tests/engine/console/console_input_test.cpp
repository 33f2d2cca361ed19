// The console's input side: line editing, history, TAB completion, ENTER through the command
// buffer, key routing between the console and the key bindings, toggling and the slide.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "console/console.h"
#include "console/console_keys.h"
#include "console/input_history.h"
#include "console/line_editor.h"
#include "console/tab_completion.h"
#include "host/host_core.h"

namespace nq {
namespace {

CvarSpec plain_cvar(const char* name, const char* value) {
    CvarSpec spec;
    spec.name = name;
    spec.default_value = value;
    return spec;
}

InputEvent key_event(const char* key, bool down, bool repeat = false) {
    InputEvent event;
    event.type = InputEventType::Key;
    event.key = key;
    event.down = down;
    event.repeat = repeat;
    return event;
}

InputEvent text_event(const char* text) {
    InputEvent event;
    event.type = InputEventType::Text;
    std::strncpy(event.text.data(), text, event.text.size() - 1);
    return event;
}

// A host whose output goes to the console (as the engine wires it), with a "probe" command
// and "+probe" / "-probe" that record how they were called.
class ConsoleFixture : public ::testing::Test {
  protected:
    ConsoleFixture() {
        host.set_print([this](std::string_view text) {
            console.print(text);
            output += text;
        });
        for (const char* name : {"probe", "+probe", "-probe"}) {
            host.commands().add_command(name, [this, name](const CommandArgs& args) {
                calls.push_back(std::string(name) + "(" + std::string(args.args()) + ")");
            });
        }
    }

    void press(const char* key) {
        console.handle_event(key_event(key, true));
        console.handle_event(key_event(key, false));
    }
    void type(const char* text) { console.handle_event(text_event(text)); }
    void open() {
        if (!console.is_open()) press("`");
    }
    // Runs what the buffer holds (one frame).
    void frame() { host.commands().execute(); }
    const std::string& line() const { return console.input().line().text(); }
    size_t cursor() const { return console.input().line().cursor(); }

    HostCore host;
    Console console{host};
    std::string output;
    std::vector<std::string> calls;
};

TEST(LineEditor, EditingSequenceProducesTheExactLine) {
    LineEditor line;
    line.insert("helo");
    line.move_left();
    line.insert("l");
    EXPECT_EQ(line.text(), "hello");
    EXPECT_EQ(line.cursor(), 4u);
    line.move_home();
    line.erase();  // DEL at the start
    EXPECT_EQ(line.text(), "ello");
    line.move_end();
    line.backspace();
    EXPECT_EQ(line.text(), "ell");
    line.move_home();
    line.backspace();  // nothing before the cursor
    line.move_left();
    EXPECT_EQ(line.cursor(), 0u);
    line.insert("sh");
    EXPECT_EQ(line.text(), "shell");
    line.move_end();
    line.move_right();
    line.erase();  // nothing at the end
    EXPECT_EQ(line.text(), "shell");
    EXPECT_EQ(line.cursor(), 5u);
}

TEST(LineEditor, OnlyPrintableAsciiUpToTheLimit) {
    LineEditor line;
    line.insert("a\tb\x01\xC3\xA9z");  // tab, control byte and UTF-8 "é" are dropped
    EXPECT_EQ(line.text(), "abz");
    line.insert(std::string(300, 'x'));
    EXPECT_EQ(line.text().size(), kMaxInputLineBytes);
    EXPECT_EQ(line.cursor(), kMaxInputLineBytes);
    line.set("short", 99);
    EXPECT_EQ(line.cursor(), 5u);
}

TEST(InputHistory, BrowsesBackAndForthAndRestoresTheDraft) {
    InputHistory history;
    history.add("a");
    history.add("b");
    history.add("c");
    EXPECT_EQ(history.older("draft"), "c");
    EXPECT_EQ(history.older("ignored"), "b");
    EXPECT_EQ(history.older(""), "a");
    EXPECT_EQ(history.older(""), std::nullopt);  // at the oldest
    EXPECT_EQ(history.newer(), "b");
    EXPECT_EQ(history.newer(), "c");
    EXPECT_EQ(history.newer(), "draft");
    EXPECT_EQ(history.newer(), std::nullopt);
}

TEST(InputHistory, SkipsEmptyAndRepeatedLinesAndDropsTheOldest) {
    InputHistory history(32);
    history.add("");
    EXPECT_EQ(history.size(), 0u);
    history.add("x");
    history.add("x");
    EXPECT_EQ(history.size(), 1u);
    for (int i = 0; i < 40; ++i) history.add("line" + std::to_string(i));
    EXPECT_EQ(history.size(), 32u);
    EXPECT_EQ(history.entry(0), "line39");
    EXPECT_EQ(history.entry(31), "line8");
}

TEST(ConsoleKeys, PrintableAndEditingKeysBelongToTheConsole) {
    EXPECT_TRUE(is_console_key("a"));
    EXPECT_TRUE(is_console_key("UPARROW"));
    EXPECT_TRUE(is_console_key("PGDN"));
    EXPECT_FALSE(is_console_key("F1"));
    EXPECT_FALSE(is_console_key("MOUSE1"));
    EXPECT_FALSE(is_console_key("ESCAPE"));
}

TEST_F(ConsoleFixture, TypedTextAndEditingKeys) {
    open();
    type("echo hllo");
    press("LEFTARROW");
    press("LEFTARROW");
    press("LEFTARROW");
    type("e");
    EXPECT_EQ(line(), "echo hello");
    EXPECT_EQ(cursor(), 7u);
    press("HOME");
    press("DEL");
    press("END");
    press("BACKSPACE");
    EXPECT_EQ(line(), "cho hell");
    press("RIGHTARROW");  // already at the end
    EXPECT_EQ(cursor(), 8u);
    type("~`");  // the console key's characters never type
    EXPECT_EQ(line(), "cho hell");
}

TEST_F(ConsoleFixture, EnterEchoesAndRunsThroughTheBuffer) {
    open();
    type("probe 42");
    press("ENTER");
    EXPECT_EQ(output, "]probe 42\n");
    EXPECT_EQ(console.text().line(0), "]probe 42");
    EXPECT_TRUE(calls.empty());  // buffered, not run yet
    EXPECT_EQ(line(), "");
    frame();
    EXPECT_EQ(calls, (std::vector<std::string>{"probe(42)"}));
}

TEST_F(ConsoleFixture, HistoryKeysRecallEnteredLines) {
    open();
    for (const char* text : {"first", "second"}) {
        type(text);
        press("ENTER");
    }
    type("dra");
    press("UPARROW");
    EXPECT_EQ(line(), "second");
    EXPECT_EQ(cursor(), 6u);
    press("UPARROW");
    EXPECT_EQ(line(), "first");
    press("UPARROW");
    EXPECT_EQ(line(), "first");
    press("DOWNARROW");
    EXPECT_EQ(line(), "second");
    press("DOWNARROW");
    EXPECT_EQ(line(), "dra");
}

TEST_F(ConsoleFixture, TabCompletesAUniqueName) {
    host.commands().add_command("zap_alpha", [](const CommandArgs&) {});
    host.cvars().register_cvar(plain_cvar("zip_one", "1"));
    open();
    type("zi");
    press("TAB");
    EXPECT_EQ(line(), "zip_one ");
    EXPECT_EQ(cursor(), 8u);
    // Case-insensitive, spelled as registered.
    console.input().line().clear();
    type("ZAP");
    press("TAB");
    EXPECT_EQ(line(), "zap_alpha ");
}

TEST_F(ConsoleFixture, TabListsAmbiguousNamesAndCompletesTheCommonPrefix) {
    host.commands().add_command("zap_alpha", [](const CommandArgs&) {});
    host.commands().add_command("zap_beta", [](const CommandArgs&) {});
    host.commands().set_alias("zap_gamma", "echo g");
    host.cvars().register_cvar(plain_cvar("zap_delta", "0"));
    open();
    type("za");
    output.clear();
    press("TAB");
    EXPECT_EQ(line(), "zap_");
    EXPECT_EQ(cursor(), 4u);
    EXPECT_EQ(output, "]za\n  zap_alpha\n  zap_beta\n  zap_delta\n  zap_gamma\n");
    // Typing on narrows it down to one.
    type("g");
    press("TAB");
    EXPECT_EQ(line(), "zap_gamma ");
}

TEST_F(ConsoleFixture, TabCompletesOnlyCommandNames) {
    host.cvars().register_cvar(plain_cvar("zip_one", "1"));
    open();
    type("echo zi");  // an argument: left alone
    press("TAB");
    EXPECT_EQ(line(), "echo zi");
    console.input().line().clear();
    type("echo x; zi");  // the second command's name
    press("TAB");
    EXPECT_EQ(line(), "echo x; zip_one ");
    console.input().line().clear();
    type("nothing_matches_this");
    press("TAB");
    EXPECT_EQ(line(), "nothing_matches_this");
}

TEST(TabCompletion, CandidatesAndCommonPrefix) {
    HostCore host;
    host.commands().add_command("Cl_Alpha", [](const CommandArgs&) {});
    host.cvars().register_cvar(plain_cvar("cl_alphabet", "1"));
    std::vector<std::string> names = completion_candidates(host.commands(), "CL_AL");
    EXPECT_EQ(names, (std::vector<std::string>{"Cl_Alpha", "cl_alphabet"}));
    EXPECT_EQ(common_prefix(names), "Cl_Alpha");
    EXPECT_EQ(common_prefix({"abc", "ABD"}), "ab");
    EXPECT_EQ(common_prefix({}), "");
    // Completing in the middle of a line keeps what follows.
    CompletionResult result = complete_command(host.commands(), "cl_alphab; echo", 9);
    EXPECT_EQ(result.line, "cl_alphabet ; echo");
    EXPECT_EQ(result.cursor, 12u);
}

TEST_F(ConsoleFixture, PageKeysScrollTheText) {
    for (int i = 0; i < 40; ++i) console.print("line " + std::to_string(i) + "\n");
    open();
    press("PGUP");
    EXPECT_EQ(console.text().scroll_rows(), static_cast<size_t>(kPageScrollRows));
    press("MWHEELUP");
    EXPECT_EQ(console.text().scroll_rows(),
              static_cast<size_t>(kPageScrollRows + kWheelScrollRows));
    press("PGDN");
    press("PGDN");
    EXPECT_EQ(console.text().scroll_rows(), 0u);
    console.handle_event(key_event("CTRL", true));
    press("HOME");
    EXPECT_EQ(console.text().scroll_rows(), 39u);
    press("END");
    console.handle_event(key_event("CTRL", false));
    EXPECT_EQ(console.text().scroll_rows(), 0u);
    // ENTER brings the view back to the bottom.
    press("PGUP");
    press("ENTER");
    EXPECT_EQ(console.text().scroll_rows(), 0u);
}

TEST_F(ConsoleFixture, ConsoleKeyAndEscapeToggle) {
    EXPECT_FALSE(console.is_open());
    press("`");
    EXPECT_TRUE(console.is_open());
    press("ESCAPE");
    EXPECT_FALSE(console.is_open());
    press("ESCAPE");
    EXPECT_TRUE(console.is_open());
    console.handle_event(key_event("`", true));
    console.handle_event(key_event("`", true, /*repeat=*/true));  // held: one toggle
    EXPECT_FALSE(console.is_open());
    host.commands().add_text("toggleconsole\n");
    frame();
    EXPECT_TRUE(console.is_open());
}

TEST_F(ConsoleFixture, TextGoesToTheLineOnlyWhileOpen) {
    EXPECT_FALSE(console.handle_event(text_event("abc")));
    open();
    EXPECT_TRUE(console.handle_event(text_event("abc")));
    EXPECT_EQ(line(), "abc");
}

TEST_F(ConsoleFixture, BindingsRunOnPressWhileClosed) {
    host.bindings().bind("k", "probe pressed");
    console.handle_event(key_event("k", true));
    console.handle_event(key_event("k", true, /*repeat=*/true));  // ignored
    console.handle_event(key_event("k", false));
    frame();
    EXPECT_EQ(calls, (std::vector<std::string>{"probe(pressed)"}));
}

TEST_F(ConsoleFixture, PlusBindingsSendMinusOnRelease) {
    host.bindings().bind("j", "+probe");
    console.handle_event(key_event("j", true));
    frame();
    EXPECT_EQ(calls, (std::vector<std::string>{"+probe(j)"}));
    console.handle_event(key_event("j", false));
    frame();
    EXPECT_EQ(calls, (std::vector<std::string>{"+probe(j)", "-probe(j)"}));
}

TEST_F(ConsoleFixture, ReleaseArrivesEvenAfterTheConsoleOpened) {
    host.bindings().bind("j", "+probe");
    console.handle_event(key_event("j", true));
    press("`");  // console opens while j is held
    console.handle_event(key_event("j", false));
    frame();
    EXPECT_EQ(calls, (std::vector<std::string>{"+probe(j)", "-probe(j)"}));
    // A press while open types instead, and its release runs nothing.
    calls.clear();
    console.handle_event(key_event("j", true));
    console.handle_event(key_event("j", false));
    frame();
    EXPECT_TRUE(calls.empty());
}

TEST_F(ConsoleFixture, NonConsoleKeysKeepTheirBindingsWhileOpen) {
    host.bindings().bind("F5", "probe f5");
    host.bindings().bind("a", "probe a");
    open();
    press("F5");
    press("a");  // a console key: not its binding
    frame();
    EXPECT_EQ(calls, (std::vector<std::string>{"probe(f5)"}));
}

TEST_F(ConsoleFixture, FocusLossReleasesHeldActions) {
    host.bindings().bind("w", "+probe");
    console.handle_event(key_event("w", true));
    EXPECT_EQ(console.keys().held_actions(), 1u);
    InputEvent lost;
    lost.type = InputEventType::FocusLost;
    console.handle_event(lost);
    frame();
    EXPECT_EQ(calls, (std::vector<std::string>{"+probe(w)", "-probe(w)"}));
    console.handle_event(key_event("w", false));  // the late release runs nothing more
    frame();
    EXPECT_EQ(calls.size(), 2u);
}

TEST_F(ConsoleFixture, SlidesAtScrConspeed) {
    console.update(10.0);
    open();
    EXPECT_FLOAT_EQ(console.height_fraction(), 0.0f);
    console.update(10.1);  // 300 lines of 200 per second: 0.15 of the screen in 0.1 s
    EXPECT_NEAR(console.height_fraction(), 0.15f, 1e-5f);
    console.update(11.0);
    EXPECT_FLOAT_EQ(console.height_fraction(), kOpenConsoleFraction);
    press("`");
    console.update(11.2);
    EXPECT_NEAR(console.height_fraction(), 0.2f, 1e-5f);
    host.cvars().set("scr_conspeed", "0");  // no slide
    console.update(11.21);
    EXPECT_FLOAT_EQ(console.height_fraction(), 0.0f);
}

TEST_F(ConsoleFixture, HalfTheScreenWhenOpen) {
    host.cvars().set("scr_conspeed", "0");
    console.set_screen_size(800, 600);
    open();
    console.update(1.0);
    EXPECT_EQ(console.height_pixels(), 300);
}

TEST_F(ConsoleFixture, CvarsAreRegisteredWithDescriptions) {
    for (const char* name : {"con_notifytime", "scr_centertime", "scr_conspeed", "con_scale"}) {
        const Cvar* cvar = host.cvars().find(name);
        ASSERT_NE(cvar, nullptr) << name;
        EXPECT_FALSE(cvar->description().empty()) << name;
    }
    EXPECT_EQ(host.cvars().find("con_notifytime")->string(), "3");
    EXPECT_EQ(host.cvars().find("scr_centertime")->string(), "2");
    EXPECT_DOUBLE_EQ(console.notify_seconds(), 3.0);
    host.cvars().set("con_notifytime", "5");
    EXPECT_DOUBLE_EQ(console.notify_seconds(), 5.0);
}

TEST_F(ConsoleFixture, LayoutFollowsScreenSizeAndConScale) {
    console.set_screen_size(1280, 960);
    EXPECT_EQ(console.layout().scale, 2);
    EXPECT_EQ(console.text().columns(), 1280u / 16 - 2);
    host.cvars().set("con_scale", "1");
    console.update(0);
    EXPECT_EQ(console.layout().scale, 1);
    EXPECT_EQ(console.text().columns(), 158u);
    InputEvent resize;
    resize.type = InputEventType::Resize;
    resize.width = 320;
    resize.height = 200;
    console.handle_event(resize);
    EXPECT_EQ(console.text().columns(), 38u);
}

TEST_F(ConsoleFixture, NotifyAndCenterPrintUseTheConsoleClock) {
    console.update(100.0);
    console.print("hello\n");
    console.center_print("centre");
    EXPECT_DOUBLE_EQ(console.text().line_time(0), 100.0);
    EXPECT_TRUE(console.center().visible(101.5, console.center_seconds()));
    EXPECT_FALSE(console.center().visible(102.0, console.center_seconds()));
    // Toggling the console clears the notify area (its lines were seen).
    open();
    std::array<std::string_view, 4> rows;
    EXPECT_EQ(console.text().notify_rows(100.5, 3.0, rows), 0u);
}

TEST_F(ConsoleFixture, ClearCommandEmptiesTheScrollback) {
    console.print("a\nb\n");
    host.commands().add_text("clear\n");
    frame();
    EXPECT_EQ(console.text().line_count(), 0u);
}

TEST(ConsoleLifetime, CommandsGoWithTheConsole) {
    HostCore host;
    {
        Console console(host);
        EXPECT_TRUE(host.commands().has_command("toggleconsole"));
        EXPECT_TRUE(host.commands().has_command("clear"));
    }
    EXPECT_FALSE(host.commands().has_command("toggleconsole"));
    EXPECT_FALSE(host.commands().has_command("clear"));
    host.commands().add_text("toggleconsole\n");
    host.commands().execute();  // no dangling console behind it
}

TEST(ConsoleLifetime, LeavesCommandsItDidNotAdd) {
    HostCore host;
    bool ran = false;
    host.commands().add_command("clear", [&](const CommandArgs&) { ran = true; });
    { Console console(host); }
    host.commands().add_text("clear\n");
    host.commands().execute();
    EXPECT_TRUE(ran);
}

}  // namespace
}  // namespace nq
