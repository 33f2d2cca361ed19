// What a client is sent about the world every frame (Quake's SV_WriteClientdataToMessage and
// SV_WriteEntitiesToClient), and the baselines the entity updates are deltas against.
#pragma once

#include <vector>

#include "server/server_level.h"

namespace nq::server {

// Records every entity's baseline and appends svc_spawnbaseline(2) messages to the signon.
void write_baselines(ServerLevel& level);
// svc_damage and svc_setangle (when `consume`: they are sent once, then cleared) and
// svc_clientdata for the player's edict.
void write_client_data(ServerLevel& level, uint32_t player, std::vector<uint8_t>& out,
                       bool consume);
// Updates of every entity the player's eye can see (its PVS), against the baselines.
void write_entities(ServerLevel& level, uint32_t player, std::vector<uint8_t>& out);

}  // namespace nq::server
