// What the server needs from the engine around it: files, console output, cvars and the command
// buffer. The engine implements it; tests implement it with plain maps and vectors.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace nq::server {

class ServerHost {
  public:
    virtual ~ServerHost() = default;
    // A game file ("progs.dat", "maps/start.bsp") through the virtual filesystem.
    virtual std::optional<std::vector<uint8_t>> read_file(std::string_view path) = 0;
    virtual void print(std::string_view text) = 0;        // console
    virtual void debug_print(std::string_view text) = 0;  // console when `developer` is on
    virtual float cvar_value(std::string_view name) = 0;  // 0 for an unknown cvar
    virtual std::string cvar_string(std::string_view name) = 0;
    virtual void set_cvar(std::string_view name, std::string_view value) = 0;
    virtual void add_command(std::string_view text) = 0;  // appended to the command buffer
};

}  // namespace nq::server
