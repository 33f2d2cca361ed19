// The game server's host for tests: files from the LibreQuake game directory (or from
// `overrides`, to feed a broken progs or map), cvars in a map, console text kept for checks.
#pragma once

#include <cstdlib>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "common/file_io.h"
#include "server/server_host.h"
#include "support/test_data.h"

namespace nq::test {

class DataServerHost : public server::ServerHost {
  public:
    std::map<std::string, std::vector<uint8_t>, std::less<>> overrides;
    std::map<std::string, std::string, std::less<>> cvars{{"skill", "1"}, {"sv_aim", "1"}};
    std::string console;

    std::optional<std::vector<uint8_t>> read_file(std::string_view path) override {
        if (auto it = overrides.find(path); it != overrides.end()) return it->second;
        auto bytes = nq::read_file(lq1_dir() + "/" + std::string(path));
        if (!bytes) return std::nullopt;
        return std::move(*bytes);
    }
    void print(std::string_view text) override { console += text; }
    void debug_print(std::string_view) override {}
    float cvar_value(std::string_view name) override {
        auto it = cvars.find(name);
        return it == cvars.end() ? 0.0f : std::strtof(it->second.c_str(), nullptr);
    }
    std::string cvar_string(std::string_view name) override {
        auto it = cvars.find(name);
        return it == cvars.end() ? "" : it->second;
    }
    void set_cvar(std::string_view name, std::string_view value) override {
        cvars[std::string(name)] = std::string(value);
    }
    void add_command(std::string_view text) override { console += "cmd: " + std::string(text); }
};

}  // namespace nq::test
