#include "app/game/engine_server_host.h"

#include "fs/vfs.h"

namespace nq {

std::optional<std::vector<uint8_t>> EngineServerHost::read_file(std::string_view path) {
    if (!vfs_) return std::nullopt;
    auto bytes = vfs_->read(std::string(path));
    if (!bytes) return std::nullopt;
    return std::move(bytes.value());
}

void EngineServerHost::debug_print(std::string_view text) {
    if (cvar_value("developer") != 0) print_(text);
}

float EngineServerHost::cvar_value(std::string_view name) {
    const Cvar* cvar = host_.cvars().find(name);
    return cvar ? cvar->value() : 0.0f;
}

std::string EngineServerHost::cvar_string(std::string_view name) {
    const Cvar* cvar = host_.cvars().find(name);
    return cvar ? cvar->string() : std::string();
}

void EngineServerHost::set_cvar(std::string_view name, std::string_view value) {
    host_.cvars().set(name, value);
}

}  // namespace nq
