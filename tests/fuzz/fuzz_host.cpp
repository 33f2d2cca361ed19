// Fuzzes the host core's command language: arbitrary text run as console input and as an
// exec'd script, over several frames, with cvars, aliases, bindings and a config round trip.
// Memory stays bounded by the command buffer limit and the per-frame expansion guard.
#include <string>
#include <vector>

#include "fuzz_target.h"
#include "host/config_writer.h"
#include "host/host_core.h"

namespace {

nq::test::SeedFile seed(std::string name, const std::string& text) {
    return {std::move(name), std::vector<uint8_t>(text.begin(), text.end())};
}

std::vector<nq::test::SeedFile> host_seeds() {
    return {
        seed("config.cfg",
             "unbindall\nbind \"ESCAPE\" \"togglemenu\"\nbind \"x\" say \"hi there\"\n"
             "seta sensitivity \"4.5\"\nseta r_outline \"1\"\n"),
        seed("aliases.cfg",
             "alias show \"echo [$1] [$2] $* $0 $$\"; show a \"b c\"\n"
             "alias loop \"echo tick; wait; loop\"; loop\nalias a b; alias b a; a\n"),
        seed("commands.cfg",
             "set x 1; toggle x; toggle x a b c; reset x; cvarlist; cmdlist un; bindlist\n"
             "r_edge 99; r_edge text; version 2 // comment\nexec script.cfg\n\"unterminated\n"),
        seed("nesting.cfg", "alias boom \"boom;boom\"; boom; exec script.cfg; wait; wait\n"),
    };
}

std::string without_comments(const std::string& text) {
    std::string out;
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        end = end == std::string::npos ? text.size() : end + 1;
        if (text.compare(start, 2, "//") != 0) out.append(text, start, end - start);
        start = end;
    }
    return out;
}

// config.cfg written, exec'd into a fresh host and written again must give the same commands
// (values that cannot be written are left out with a comment, the same both times).
void check_config_round_trip(const nq::HostCore& host) {
    std::string saved = nq::config_text(host.cvars(), host.bindings());
    if (saved.size() >= nq::kDefaultCommandBufferBytes) return;  // would not fit in the buffer
    nq::HostCore reloaded;
    reloaded.set_file_reader(
        [&](const std::string&) -> std::optional<std::string> { return saved; });
    reloaded.commands().add_text("exec config.cfg");
    reloaded.commands().execute();
    std::string again = nq::config_text(reloaded.cvars(), reloaded.bindings());
    if (without_comments(again) != without_comments(saved)) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
    nq::fuzz::handle_write_seeds(*argc, *argv, host_seeds());
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string text(reinterpret_cast<const char*>(data), size);
    nq::HostCore host(16 * 1024);  // small buffer: runaway scripts hit the limit quickly
    host.set_print([](std::string_view) {});
    // `exec` of any name reads the input itself, a few times (each exec of a 16 KiB script
    // costs a full parse; the exec-loop guard is covered by the unit tests).
    int reads_left = 4;
    host.set_file_reader([&](const std::string&) -> std::optional<std::string> {
        if (reads_left == 0) return std::nullopt;
        --reads_left;
        return text;
    });

    nq::CvarSpec edge{"r_edge", "1", nq::kCvarArchive, "edge", 0.0f, 10.0f};
    nq::CvarSpec version{"version", "0.1", nq::kCvarReadOnly, "", {}, {}};
    host.cvars().register_cvar(edge);
    host.cvars().register_cvar(version);

    host.commands().add_text(text);
    for (int frame = 0; frame < 8; ++frame) host.commands().execute();
    // Plugin-style re-registration after the script ran.
    host.cvars().register_cvar(edge, 2);
    host.release_owner(2);
    check_config_round_trip(host);
    return 0;
}
