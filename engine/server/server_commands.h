// The console commands that act on the local player in the running game (Quake's host_cmd.c):
// cheats (god, noclip, fly, notarget, give, setpos), kill, and status. Each returns the line to
// print.
#pragma once

#include <string>
#include <string_view>

#include "server/server_level.h"

namespace nq::server {

std::string toggle_god(ServerLevel& level);
std::string toggle_notarget(ServerLevel& level);
std::string toggle_noclip(ServerLevel& level);
std::string toggle_fly(ServerLevel& level);
// give <s|n|r|c|h|a|2..8> [amount]
std::string give(ServerLevel& level, std::string_view what, float amount);
// Runs QuakeC's ClientKill for the player; "" on success, else the QuakeC error.
std::string kill_player(ServerLevel& level);
std::string status_text(ServerLevel& level);
// QuakeSpasm's setpos: the player to `origin`, standing still (a cheat, like noclip).
std::string set_position(ServerLevel& level, const Vec3f& origin);

}  // namespace nq::server
