// LiveGame::load: a saved game in place of a new level; the client then receives its signon
// like any other level's.
#include "app/sessions/live_game.h"
#include "server/savegame.h"

namespace nq {

std::string LiveGame::load(const server::LoadedGame& game, const server::ServerSettings& settings) {
    const server::SpawnResult result = server_.load_game(game, settings);
    if (!result.error.empty()) return result.error;
    level_started();
    return {};
}

}  // namespace nq
