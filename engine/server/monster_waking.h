// Waking a level's monsters the way a player would, for benchmarks and tests that need them
// hunting: the player is stood, for a second each, in clear view of one monster after another
// (a spot `distance` units away that a player-sized box reaches with nothing in between).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "server/server.h"
#include "server/server_level.h"

namespace nq::server {

// Living monsters (FL_MONSTER, health > 0).
std::vector<uint32_t> living_monsters(ServerLevel& level);
// How many of them have the player as their enemy.
int monsters_hunting_player(ServerLevel& level);
// A clear spot `distance` units from monster `m`, level with it.
std::optional<vm::Vec3f> clear_spot_near(ServerLevel& level, uint32_t m, float distance);
// Puts the player at `at`, standing still.
void place_player(ServerLevel& level, const vm::Vec3f& at);
// Visits monsters until `share` of them hunt the player (or all were visited). False when the
// server failed meanwhile.
bool wake_monsters(Server& server, double share);

}  // namespace nq::server
