#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <unistd.h>

#include "common/file_io.h"
#include "host/config_writer.h"
#include "host_test_fixture.h"

namespace nq {
namespace {

using test::HostFixture;

CvarSpec spec(std::string name, std::string value, uint32_t flags) {
    CvarSpec s;
    s.name = std::move(name);
    s.default_value = std::move(value);
    s.flags = flags;
    return s;
}

// The engine's and one plugin's cvars, as in a session.
void register_session_cvars(CvarRegistry& cvars) {
    cvars.register_cvar(spec("sensitivity", "3", kCvarArchive));
    cvars.register_cvar(spec("Volume", "0.7", kCvarArchive));
    cvars.register_cvar(spec("r_outline", "1", kCvarArchive | kCvarPlugin), 5);
    cvars.register_cvar(spec("version", "0.1", kCvarArchive | kCvarReadOnly));  // never saved
    cvars.register_cvar(spec("host_speeds", "0", 0));                           // not archived
}

class HostConfig : public HostFixture {};

TEST_F(HostConfig, WritesSortedBindingsThenArchivedCvars) {
    register_session_cvars(host.cvars());
    run("sensitivity 4.5; volume \"0.25\"; host_speeds 1; seta r_later \"a b\"");
    run("bind w +forward; bind ESCAPE togglemenu; bind ~ toggleconsole; bind x say \"hi there\"");
    EXPECT_EQ(config_text(host.cvars(), host.bindings()),
              "// Written by nprquake on exit. Put your own commands in autoexec.cfg.\n"
              "unbindall\n"
              "bind \"ESCAPE\" \"togglemenu\"\n"
              "bind \"`\" \"toggleconsole\"\n"
              "bind \"w\" \"+forward\"\n"
              "bind \"x\" say \"hi there\"\n"
              "seta r_later \"a b\"\n"
              "seta r_outline \"1\"\n"
              "seta sensitivity \"4.5\"\n"
              "seta Volume \"0.25\"\n");
}

TEST_F(HostConfig, ExecOfTheWrittenConfigRestoresEverything) {
    register_session_cvars(host.cvars());
    run("sensitivity 6; r_outline 0; seta r_later \"x;y\"; seta cl_name \"\"");
    run("bind SPACE +jump; bind mouse1 +attack; bind x say \"hi there\"; bind \";\" \"echo a;b\"");
    std::string saved = config_text(host.cvars(), host.bindings());

    // The next session: config.cfg runs before the plugin that owns r_outline is loaded.
    HostCore next;
    std::string out;
    next.set_print([&](std::string_view t) { out += t; });
    next.set_file_reader([&](const std::string& path) -> std::optional<std::string> {
        if (path == "config.cfg") return saved;
        return std::nullopt;
    });
    next.cvars().register_cvar(spec("sensitivity", "3", kCvarArchive));
    next.cvars().register_cvar(spec("Volume", "0.7", kCvarArchive));
    next.bindings().bind("F1", "help");  // unbindall in the config clears stale bindings
    next.commands().add_text("exec config.cfg");
    next.commands().execute();
    EXPECT_EQ(out, "execing config.cfg\n");

    EXPECT_EQ(next.bindings().all(), host.bindings().all());
    EXPECT_EQ(next.cvars().find("sensitivity")->string(), "6");
    EXPECT_EQ(next.cvars().find("r_later")->string(), "x;y");
    EXPECT_EQ(next.cvars().find("cl_name")->string(), "");
    // Not registered yet: kept as an archived user cvar...
    const Cvar* early = next.cvars().find("r_outline");
    ASSERT_NE(early, nullptr);
    EXPECT_EQ(early->flags(), uint32_t{kCvarUserCreated | kCvarArchive});
    // ...and applied when the plugin registers it.
    Cvar* outline = next.cvars().register_cvar(spec("r_outline", "1", kCvarArchive), 9);
    EXPECT_EQ(outline->string(), "0");
    EXPECT_EQ(next.cvars().find("version"), nullptr);

    // Saving again gives the same file.
    next.cvars().register_cvar(spec("version", "0.1", kCvarArchive | kCvarReadOnly));
    next.cvars().register_cvar(spec("host_speeds", "0", 0));
    EXPECT_EQ(config_text(next.cvars(), next.bindings()), saved);
}

TEST_F(HostConfig, OutputDoesNotDependOnRegistrationOrder) {
    HostCore other;
    register_session_cvars(host.cvars());
    other.cvars().register_cvar(spec("host_speeds", "0", 0));
    other.cvars().register_cvar(spec("version", "0.1", kCvarArchive | kCvarReadOnly));
    other.cvars().register_cvar(spec("r_outline", "1", kCvarArchive | kCvarPlugin), 5);
    other.cvars().register_cvar(spec("Volume", "0.7", kCvarArchive));
    other.cvars().register_cvar(spec("sensitivity", "3", kCvarArchive));
    host.bindings().bind("a", "1");
    host.bindings().bind("b", "2");
    other.bindings().bind("b", "2");
    other.bindings().bind("a", "1");
    EXPECT_EQ(config_text(host.cvars(), host.bindings()),
              config_text(other.cvars(), other.bindings()));
}

TEST_F(HostConfig, UnwritableValuesAreLeftOutWithAComment) {
    host.cvars().register_cvar(spec("r_weird", "", kCvarArchive));
    host.cvars().set("r_weird", "two\nlines");
    host.cvars().register_cvar(spec("r_quote", "", kCvarArchive));
    host.cvars().set("r_quote", "\"a b");  // a leading quote and a space: no syntax for it
    host.cvars().register_cvar(spec("r_word", "", kCvarArchive));
    host.cvars().set("r_word", "ab\"c");  // a single word with a quote: written bare
    EXPECT_EQ(config_text(host.cvars(), host.bindings()),
              "// Written by nprquake on exit. Put your own commands in autoexec.cfg.\n"
              "unbindall\n"
              "// not saved: the value of cvar \"r_quote\" cannot be written as a command\n"
              "// not saved: the value of cvar \"r_weird\" cannot be written as a command\n"
              "seta r_word ab\"c\n");
}

TEST_F(HostConfig, SaveConfigWritesTheFile) {
    register_session_cvars(host.cvars());
    // Per process: the same test may run at once from another build tree.
    std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                ("nq_host_config_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    std::string path = (dir / "config.cfg").string();
    EXPECT_EQ(save_config(path, host.cvars(), host.bindings()), "");
    auto bytes = read_file(path);
    ASSERT_TRUE(bytes.ok());
    EXPECT_EQ(std::string(bytes->begin(), bytes->end()),
              config_text(host.cvars(), host.bindings()));
    std::filesystem::remove_all(dir);
    std::string missing = (dir / "missing" / "config.cfg").string();
    EXPECT_EQ(save_config(missing, host.cvars(), host.bindings()),
              missing + ": cannot create: No such file or directory");
}

}  // namespace
}  // namespace nq
