// The engine as the game server sees it (server::ServerHost): files through the virtual
// filesystem, text to the console, cvars and the command buffer of the host core.
#pragma once

#include <functional>

#include "host/host_core.h"
#include "server/server_host.h"

namespace nq {

class Vfs;

class EngineServerHost final : public server::ServerHost {
  public:
    EngineServerHost(HostCore& host, const Vfs* vfs, std::function<void(std::string_view)> print)
        : host_(host), vfs_(vfs), print_(std::move(print)) {}

    std::optional<std::vector<uint8_t>> read_file(std::string_view path) override;
    void print(std::string_view text) override { print_(text); }
    void debug_print(std::string_view text) override;
    float cvar_value(std::string_view name) override;
    std::string cvar_string(std::string_view name) override;
    void set_cvar(std::string_view name, std::string_view value) override;
    void add_command(std::string_view text) override { host_.commands().add_text(text); }

  private:
    HostCore& host_;
    const Vfs* vfs_;
    std::function<void(std::string_view)> print_;
};

}  // namespace nq
