// serverbench: the game server alone, headless and without a client, timed per server frame.
// It starts a map with the game's progs, turns god mode on, then wakes the monsters the way a
// player would: it stands the player in clear view of each monster in turn (a spot 256 units
// away with nothing between them) for a second, until the wanted share hunts the player. Then
// it leaves the player at a spot among them and times the frames that follow: physics, QuakeC
// and the messages the client would receive.
//
// usage: serverbench [-basedir DIR] [-game MOD] [--map NAME] [--seconds S] [--hunting FRACTION]
//                    [--skill N]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "fs/vfs.h"
#include "server/monster_waking.h"
#include "server/server.h"
#include "server/server_commands.h"
#include "server/server_level.h"

namespace {

using namespace nq;
using namespace nq::server;

constexpr double kFrame = 1.0 / 72;

class VfsHost : public ServerHost {
  public:
    explicit VfsHost(const Vfs& vfs) : vfs_(vfs) {}
    std::optional<std::vector<uint8_t>> read_file(std::string_view path) override {
        auto bytes = vfs_.read(std::string(path));
        if (!bytes) return std::nullopt;
        return std::move(bytes.value());
    }
    void print(std::string_view) override {}
    void debug_print(std::string_view) override {}
    float cvar_value(std::string_view name) override { return name == "sv_aim" ? 1.0f : 0.0f; }
    std::string cvar_string(std::string_view) override { return ""; }
    void set_cvar(std::string_view, std::string_view) override {}
    void add_command(std::string_view) override {}

  private:
    const Vfs& vfs_;
};

struct Options {
    std::string basedir = "../shared/data", game = "lq1", map = "e2m3";
    double seconds = 60;
    double hunting = 0.5;
    int skill = 1;
};

bool parse(int argc, char** argv, Options& o, bool& help) {
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool has_value = i + 1 < argc;
        if (a == "-h" || a == "--help") {
            help = true;
            return false;
        }
        if (!has_value) return false;
        const std::string v = argv[++i];
        if (a == "-basedir")
            o.basedir = v;
        else if (a == "-game")
            o.game = v;
        else if (a == "--map")
            o.map = v;
        else if (a == "--seconds")
            o.seconds = std::atof(v.c_str());
        else if (a == "--hunting")
            o.hunting = std::atof(v.c_str());
        else if (a == "--skill")
            o.skill = std::atoi(v.c_str());
        else
            return false;
    }
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    bool help = false;
    if (!parse(argc, argv, o, help)) {
        std::fputs(
            "usage: serverbench [-basedir DIR] [-game MOD] [--map NAME] [--seconds S] "
            "[--hunting FRACTION] [--skill N]\n",
            help ? stdout : stderr);
        return help ? 0 : 2;
    }
    auto vfs = Vfs::mount(VfsConfig::for_game(o.basedir, o.game));
    if (!vfs) {
        std::fprintf(stderr, "serverbench: %s\n", vfs.error().message.c_str());
        return 1;
    }
    VfsHost host(*vfs);
    Server server(host);
    ServerSettings settings;
    settings.skill = o.skill;
    const auto load_start = std::chrono::steady_clock::now();
    const SpawnResult spawned = server.spawn(o.map, settings);
    if (!spawned.error.empty()) {
        std::fprintf(stderr, "serverbench: %s\n", spawned.error.c_str());
        return 1;
    }
    const double load_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - load_start)
            .count();
    ServerLevel& level = *server.level();
    toggle_god(level);
    auto run = [&](double seconds) {
        for (int i = 0; i < int(seconds * 72); ++i) {
            if (!server.frame(kFrame, {})) return false;
        }
        return true;
    };
    const size_t monsters = living_monsters(level).size();
    if (!run(2) || !wake_monsters(server, o.hunting)) {
        return std::fprintf(stderr, "serverbench: %s\n", server.error().c_str()), 1;
    }
    const int woken = monsters_hunting_player(level);
    server.clear_frame_profile();
    if (!run(o.seconds)) {
        return std::fprintf(stderr, "serverbench: %s\n", server.error().c_str()), 1;
    }
    std::vector<float> ms = server.frame_profile();
    std::sort(ms.begin(), ms.end());
    auto at = [&](double q) {
        return ms.empty() ? 0.0
                          : double(ms[std::min(ms.size() - 1, size_t(q * double(ms.size())))]);
    };
    std::printf(
        "serverbench %s: load %.0f ms; %zu monsters, %d hunting the player after waking; "
        "%zu frames: median %.3f ms, 95th %.3f ms, 99th %.3f ms, max %.3f ms; %d hunting at "
        "the end, %u edicts\n",
        o.map.c_str(), load_ms, monsters, woken, ms.size(), at(0.5), at(0.95), at(0.99),
        ms.empty() ? 0.0 : double(ms.back()), monsters_hunting_player(level),
        level.vm->num_edicts());
    return 0;
}
