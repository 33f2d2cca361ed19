#include <gtest/gtest.h>

#include <string>

#include "host/key_names.h"
#include "host/script_commands.h"
#include "host_test_fixture.h"

namespace nq {
namespace {

using test::HostFixture;

class HostCommand : public HostFixture {
  protected:
    Cvar* add_cvar(std::string name, std::string value, uint32_t flags = 0,
                   std::optional<float> lo = {}, std::optional<float> hi = {}) {
        CvarSpec s;
        s.name = std::move(name);
        s.default_value = std::move(value);
        s.flags = flags;
        s.min_value = lo;
        s.max_value = hi;
        return host.cvars().register_cvar(s);
    }
    std::string cvar(const std::string& name) { return host.cvars().find(name)->string(); }
};

// --- buffer and wait -----------------------------------------------------------------------

TEST_F(HostCommand, EchoAndUnknownCommands) {
    EXPECT_EQ(run("echo hello   \"big world\""), "hello big world\n");
    EXPECT_EQ(run("echo"), "\n");
    EXPECT_EQ(run("ECHO case"), "case\n");
    EXPECT_EQ(run("frobnicate 1 2"), "Unknown command \"frobnicate\"\n");
}

TEST_F(HostCommand, WaitDefersTheRestToTheNextFrame) {
    EXPECT_EQ(run("echo a; wait; echo b\necho c; wait\necho d"), "a\n");
    EXPECT_EQ(frame(), "b\nc\n");
    EXPECT_EQ(frame(), "d\n");
    EXPECT_EQ(frame(), "");
    EXPECT_TRUE(host.commands().buffer_empty());
}

TEST_F(HostCommand, TextAddedDuringAWaitRunsAfterWhatWasPending) {
    run("echo 1; wait; echo 2");
    host.commands().add_text("echo 3");
    EXPECT_EQ(frame(), "2\n3\n");
}

TEST_F(HostCommand, InsertedTextRunsBeforePendingText) {
    host.commands().add_text("echo last");
    host.commands().insert_text("echo first");
    EXPECT_EQ(frame(), "first\nlast\n");
}

TEST_F(HostCommand, EachAddIsWholeCommands) {
    host.commands().add_text("echo a");  // no line break: must not run into the next text
    host.commands().add_text("echo b");
    EXPECT_EQ(frame(), "a\nb\n");
}

class HostSmallBuffer : public HostFixture {
  protected:
    HostSmallBuffer() : HostFixture(64) {}
};

TEST_F(HostSmallBuffer, OverflowDropsTheTextWithAMessage) {
    host.commands().add_text("echo " + std::string(100, 'x'));
    EXPECT_EQ(output, "command buffer overflow: dropped 105 bytes\n");
    EXPECT_EQ(run("echo fits"), "fits\n");
}

// --- aliases -------------------------------------------------------------------------------

TEST_F(HostCommand, AliasRunsItsBody) {
    EXPECT_EQ(run("alias greet \"echo hello; echo world\"\ngreet"), "hello\nworld\n");
    EXPECT_EQ(run("GREET"), "hello\nworld\n");
    EXPECT_EQ(run("alias greet"), "\"greet\" is \"echo hello; echo world\"\n");
}

TEST_F(HostCommand, AliasBodyMayBeTheRawRestOfTheLine) {
    run("alias two echo \"a  b\" c");
    EXPECT_EQ(*host.commands().find_alias("two"), "echo \"a  b\" c");
    EXPECT_EQ(run("two"), "a  b c\n");
}

TEST_F(HostCommand, AliasArgumentsAreSubstituted) {
    run("alias show \"echo [$1] [$2] [$3] all=$* name=$0 cost=$$5\"");
    EXPECT_EQ(run("show a \"b c\""), "[a] [b c] [] all=a b c name=show cost=$5\n");
    // $* is the raw text: its quotes group "b c" again when the body runs.
    run("alias count \"echo $*; echo done\"");
    EXPECT_EQ(run("count x \"y;z\""), "x y;z\ndone\n");
}

TEST_F(HostCommand, AliasWithoutReferencesGetsTheArgumentsAppended) {
    run("alias say2 echo");
    EXPECT_EQ(run("say2 one two"), "one two\n");
    EXPECT_EQ(run("say2"), "\n");
}

TEST_F(HostCommand, AliasLoopIsStoppedWithAClearMessage) {
    run("alias ping pong; alias pong ping");
    EXPECT_EQ(run("ping; echo never"),
              "alias \"ping\": more than 1024 alias/exec expansions in one frame "
              "(recursive alias or exec?); command buffer cleared\n");
    EXPECT_TRUE(host.commands().buffer_empty());
    EXPECT_EQ(run("echo recovered"), "recovered\n");
}

TEST_F(HostCommand, SelfRecursionGrowingTheBufferIsStoppedToo) {
    run("alias boom \"boom; boom\"");
    std::string out = run("boom");
    EXPECT_NE(out.find("command buffer cleared\n"), std::string::npos);
    EXPECT_TRUE(host.commands().buffer_empty());
}

TEST_F(HostCommand, AliasLoopPacedByWaitIsLegitimate) {
    run("alias tick \"echo tick; wait; tick\"");
    ASSERT_EQ(run("tick"), "tick\n");
    for (int i = 0; i < 2000; ++i) ASSERT_EQ(frame(), "tick\n");  // more than the loop guard
}

TEST_F(HostCommand, AliasCannotHideCommandsOrCvars) {
    add_cvar("fov", "90");
    EXPECT_EQ(run("alias echo \"quit\""), "alias: \"echo\" is already a command\n");
    EXPECT_EQ(run("alias FOV \"quit\""), "alias: \"FOV\" is already a cvar\n");
    EXPECT_EQ(run("alias \"a b\" x"), "alias: invalid name \"a b\"\n");
    EXPECT_EQ(host.commands().list_aliases().size(), 0u);
}

TEST_F(HostCommand, AliasListAndUnalias) {
    run("alias b \"echo b\"; alias a \"echo a\"");
    EXPECT_EQ(run("alias"), "a : echo a\nb : echo b\n2 aliases\n");
    EXPECT_EQ(run("unalias a; unalias a"), "unalias: no alias named \"a\"\n");
    EXPECT_EQ(run("alias"), "b : echo b\n1 alias\n");
    EXPECT_EQ(run("alias nope"), "no alias named \"nope\"\n");
}

// --- registered commands -------------------------------------------------------------------

TEST_F(HostCommand, RegisteredCommandsGetTheirArguments) {
    std::vector<std::string> seen;
    ASSERT_TRUE(
        host.commands().add_command("r_Reload", [&](const CommandArgs& a) { seen = a.tokens(); }));
    EXPECT_FALSE(host.commands().add_command("R_RELOAD", [](const CommandArgs&) {}));
    EXPECT_FALSE(host.commands().add_command("bad name", [](const CommandArgs&) {}));
    run("r_reload shaders \"all of them\"");
    EXPECT_EQ(seen, (std::vector<std::string>{"r_reload", "shaders", "all of them"}));
}

TEST_F(HostCommand, PluginCommandsAreRemovedByOwner) {
    constexpr OwnerId kPlugin = 3;
    host.commands().add_command(
        "r_a", [](const CommandArgs&) {}, "", kPlugin);
    host.commands().add_command(
        "r_b", [](const CommandArgs&) {}, "", kPlugin);
    host.commands().add_command("r_c", [](const CommandArgs&) {});
    host.release_owner(kPlugin);
    EXPECT_FALSE(host.commands().has_command("r_a"));
    EXPECT_FALSE(host.commands().has_command("r_b"));
    EXPECT_TRUE(host.commands().has_command("r_c"));
    EXPECT_EQ(run("r_a"), "Unknown command \"r_a\"\n");
}

TEST_F(HostCommand, ACommandMayRemoveItselfWhileRunning) {
    int calls = 0;
    host.commands().add_command("once", [&](const CommandArgs&) {
        ++calls;
        host.commands().remove_command("once");
    });
    EXPECT_EQ(run("once; once"), "Unknown command \"once\"\n");
    EXPECT_EQ(calls, 1);
}

TEST_F(HostCommand, CmdlistFiltersByPrefix) {
    host.commands().add_command("unbindmore", [](const CommandArgs&) {});
    EXPECT_EQ(run("cmdlist unbind"),
              "unbind - unbind <key>: remove a key's binding\n"
              "unbindall - unbindall: remove every key binding\n"
              "unbindmore\n"
              "3 commands beginning with \"unbind\"\n");
    std::string all = run("cmdlist");
    EXPECT_NE(all.find("\n16 commands\n"), std::string::npos) << all;
}

// --- exec ----------------------------------------------------------------------------------

TEST_F(HostCommand, ExecRunsAFileBeforeTheRestOfTheLine) {
    files["test.cfg"] = "echo from file\nset x 3  // trailing comment, no final newline";
    EXPECT_EQ(run("exec test.cfg; echo after"), "execing test.cfg\nfrom file\nafter\n");
    EXPECT_EQ(cvar("x"), "3");
}

TEST_F(HostCommand, ExecOfAMissingFile) {
    EXPECT_EQ(run("exec nope.cfg"), "couldn't exec nope.cfg\n");
    EXPECT_EQ(run("exec"), "usage: exec <file>\n");
}

TEST_F(HostCommand, ExecStaysInsideTheGame) {
    files["../secret.cfg"] = "echo leaked";
    files["/etc/x.cfg"] = "echo leaked";
    EXPECT_EQ(run("exec ../secret.cfg"), "couldn't exec ../secret.cfg\n");
    EXPECT_EQ(run("exec /etc/x.cfg"), "couldn't exec /etc/x.cfg\n");
    EXPECT_TRUE(is_safe_script_path("cfg/my..cfg"));
    EXPECT_FALSE(is_safe_script_path("cfg/../../x"));
    EXPECT_FALSE(is_safe_script_path("c:\\x.cfg"));
}

TEST_F(HostCommand, ExecLoopIsStopped) {
    files["loop.cfg"] = "echo in loop\nexec loop.cfg";
    std::string out = run("exec loop.cfg");
    const std::string tail =
        "exec loop.cfg: more than 1024 alias/exec expansions in one frame "
        "(recursive alias or exec?); command buffer cleared\n";
    ASSERT_GE(out.size(), tail.size());
    EXPECT_EQ(out.substr(out.size() - tail.size()), tail);
}

// --- cvars from the console ----------------------------------------------------------------

TEST_F(HostCommand, CvarNameAsCommandShowsOrSets) {
    add_cvar("sensitivity", "3");
    EXPECT_EQ(run("sensitivity"), "\"sensitivity\" is \"3\"\n");
    EXPECT_EQ(run("Sensitivity 4.5"), "");
    EXPECT_EQ(cvar("sensitivity"), "4.5");
    EXPECT_EQ(run("sensitivity \"\""), "");
    EXPECT_EQ(cvar("sensitivity"), "");
}

TEST_F(HostCommand, ConsoleReportsRefusedAndClampedValues) {
    add_cvar("version", "0.1", kCvarReadOnly);
    add_cvar("r_edge", "1", 0, 0.0f, 10.0f);
    EXPECT_EQ(run("version 2"), "\"version\" is read-only\n");
    EXPECT_EQ(run("set version 2"), "\"version\" is read-only\n");
    EXPECT_EQ(cvar("version"), "0.1");
    EXPECT_EQ(run("r_edge 11"), "\"r_edge\" clamped to 10 (must be between 0 and 10)\n");
    EXPECT_EQ(run("r_edge thick"), "\"r_edge\" needs a number between 0 and 10; unchanged\n");
    EXPECT_EQ(cvar("r_edge"), "10");
}

TEST_F(HostCommand, SetCreatesUserCvarsAndSetaArchives) {
    EXPECT_EQ(run("set myvar hello"), "");
    const Cvar* mine = host.cvars().find("myvar");
    ASSERT_NE(mine, nullptr);
    EXPECT_EQ(mine->flags(), uint32_t{kCvarUserCreated});
    EXPECT_EQ(run("myvar"), "\"myvar\" is \"hello\"\n");  // user cvars answer to their name too
    EXPECT_EQ(run("seta r_later \"1 2 3\""), "");
    EXPECT_EQ(host.cvars().find("r_later")->flags(), uint32_t{kCvarUserCreated | kCvarArchive});
    EXPECT_EQ(cvar("r_later"), "1 2 3");
    EXPECT_EQ(run("set"), "usage: set <cvar> <value>\n");
    EXPECT_EQ(run("seta x"), "usage: seta <cvar> <value>\n");
    EXPECT_EQ(run("set bad;name 1"), "usage: set <cvar> <value>\nUnknown command \"name\"\n");
    EXPECT_EQ(run("set \"bad name\" 1"), "set: invalid cvar name \"bad name\"\n");
}

TEST_F(HostCommand, ToggleFlipsOrCycles) {
    add_cvar("r_outline", "0");
    run("toggle r_outline");
    EXPECT_EQ(cvar("r_outline"), "1");
    run("toggle r_outline");
    EXPECT_EQ(cvar("r_outline"), "0");
    add_cvar("r_style", "ink");
    run("toggle r_style ink pencil charcoal");
    EXPECT_EQ(cvar("r_style"), "pencil");
    run("toggle r_style ink pencil charcoal");
    EXPECT_EQ(cvar("r_style"), "charcoal");
    run("toggle r_style ink pencil charcoal");
    EXPECT_EQ(cvar("r_style"), "ink");
    EXPECT_EQ(run("toggle nope"), "toggle: no cvar named \"nope\"\n");
    EXPECT_EQ(run("toggle"), "usage: toggle <cvar> [value1 value2 ...]\n");
}

TEST_F(HostCommand, ResetRestoresTheDefault) {
    add_cvar("fov", "90");
    run("fov 120; reset FOV");
    EXPECT_EQ(cvar("fov"), "90");
    EXPECT_EQ(run("reset nope"), "reset: no cvar named \"nope\"\n");
}

TEST_F(HostCommand, CvarlistShowsFlagsValuesAndDescriptions) {
    CvarSpec s;
    s.name = "r_ink";
    s.default_value = "0.5";
    s.flags = kCvarArchive | kCvarPlugin;
    s.description = "ink darkness";
    host.cvars().register_cvar(s, 4);
    add_cvar("r_version", "2", kCvarReadOnly);
    add_cvar("sensitivity", "3", kCvarArchive);
    run("set r_user x");
    EXPECT_EQ(run("cvarlist R_"),
              "A P  r_ink \"0.5\" - ink darkness\n"
              "   U r_user \"x\"\n"
              " R   r_version \"2\"\n"
              "3 cvars beginning with \"R_\"\n");
    EXPECT_EQ(run("cvarlist sens"), "A    sensitivity \"3\"\n1 cvar beginning with \"sens\"\n");
    EXPECT_EQ(run("cvarlist zzz"), "0 cvars beginning with \"zzz\"\n");
    EXPECT_EQ(run("cvarlist"),
              "A P  r_ink \"0.5\" - ink darkness\n"
              "   U r_user \"x\"\n"
              " R   r_version \"2\"\n"
              "A    sensitivity \"3\"\n"
              "4 cvars\n");
}

// --- bindings ------------------------------------------------------------------------------

TEST_F(HostCommand, BindStoresByCanonicalKeyName) {
    EXPECT_EQ(run("bind escape togglemenu; bind W +forward; bind ~ toggleconsole"), "");
    EXPECT_EQ(run("bind mouse1 +attack; bind f12 screenshot; bind \";\" \"echo semi\""), "");
    const auto& all = host.bindings().all();
    EXPECT_EQ(all.size(), 6u);
    EXPECT_EQ(all.at("ESCAPE"), "togglemenu");
    EXPECT_EQ(all.at("w"), "+forward");
    EXPECT_EQ(all.at("`"), "toggleconsole");
    EXPECT_EQ(all.at("MOUSE1"), "+attack");
    EXPECT_EQ(all.at("F12"), "screenshot");
    EXPECT_EQ(all.at("SEMICOLON"), "echo semi");
    EXPECT_EQ(run("bind Escape"), "\"ESCAPE\" = \"togglemenu\"\n");
    EXPECT_EQ(run("bind BACKQUOTE"), "\"`\" = \"toggleconsole\"\n");
    EXPECT_EQ(run("bind F1"), "\"F1\" is not bound\n");
}

TEST_F(HostCommand, BindTakesTheRawRestOfTheLine) {
    run("bind x say \"hi there\"; bind y \"echo a; echo b\"");
    EXPECT_EQ(*host.bindings().binding("x"), "say \"hi there\"");
    EXPECT_EQ(*host.bindings().binding("y"), "echo a; echo b");
}

TEST_F(HostCommand, BindErrorsAndUnbinding) {
    EXPECT_EQ(run("bind"), "usage: bind <key> [command]\n");
    EXPECT_EQ(run("bind nokey +jump"), "\"nokey\" isn't a valid key\n");
    EXPECT_EQ(run("unbind F13"), "\"F13\" isn't a valid key\n");
    EXPECT_EQ(run("unbind"), "usage: unbind <key>\n");
    run("bind space +jump; bind a +moveleft; bind b \"\"");
    EXPECT_EQ(run("bindlist"), "\"SPACE\" \"+jump\"\n\"a\" \"+moveleft\"\n2 bindings\n");
    run("unbind SPACE");
    EXPECT_EQ(host.bindings().binding("space"), nullptr);
    run("unbindall");
    EXPECT_TRUE(host.bindings().all().empty());
}

TEST(HostKeyNames, CanonicalNames) {
    EXPECT_EQ(canonical_key_name("A"), "a");
    EXPECT_EQ(canonical_key_name("z"), "z");
    EXPECT_EQ(canonical_key_name("7"), "7");
    EXPECT_EQ(canonical_key_name("["), "[");
    EXPECT_EQ(canonical_key_name("enter"), "ENTER");
    EXPECT_EQ(canonical_key_name("Tab"), "TAB");
    EXPECT_EQ(canonical_key_name("BACKSPACE"), "BACKSPACE");
    EXPECT_EQ(canonical_key_name("uparrow"), "UPARROW");
    EXPECT_EQ(canonical_key_name("f1"), "F1");
    EXPECT_EQ(canonical_key_name("F12"), "F12");
    EXPECT_EQ(canonical_key_name("mouse5"), "MOUSE5");
    EXPECT_EQ(canonical_key_name("mwheelup"), "MWHEELUP");
    EXPECT_EQ(canonical_key_name("kp_enter"), "KP_ENTER");
    EXPECT_EQ(canonical_key_name("~"), "`");
    EXPECT_EQ(canonical_key_name("tilde"), "`");
    EXPECT_EQ(canonical_key_name(" "), "SPACE");
    EXPECT_EQ(canonical_key_name(";"), "SEMICOLON");
    EXPECT_EQ(canonical_key_name("\""), std::nullopt);
    EXPECT_EQ(canonical_key_name("F13"), std::nullopt);
    EXPECT_EQ(canonical_key_name(""), std::nullopt);
    EXPECT_EQ(canonical_key_name("\x80"), std::nullopt);
    // Every named key is its own canonical form.
    for (const std::string& key : named_keys()) EXPECT_EQ(canonical_key_name(key), key);
}

}  // namespace
}  // namespace nq
