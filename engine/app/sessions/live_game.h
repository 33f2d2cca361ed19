// A game played here: the local server runs at a fixed 72 Hz and its messages reach the client
// exactly as a demo's blocks do (decoded by the same decoder, applied to the same ClientState),
// with the player's own view angles in place of the recorded ones. A recorder, when set, writes
// each block to a .dem file as it is applied.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "client/client_state.h"
#include "client/demo_player.h"
#include "client/demo_recorder.h"
#include "client/player_input.h"
#include "formats/message_decoder.h"
#include "server/server.h"

namespace nq {

class LiveGame {
  public:
    static constexpr double kServerFrameTime = 1.0 / 72;  // FitzQuake's server rate

    explicit LiveGame(server::ServerHost& host);

    // Starts (or changes to) `map`; "" on success, else why not.
    std::string start(const std::string& map, const server::ServerSettings& settings,
                      server::SpawnParms parms = server::SpawnParms::fresh);
    // Starts a saved game instead (live_game_load.cpp); "" on success, else why not.
    std::string load(const server::LoadedGame& game, const server::ServerSettings& settings);
    void stop() { server_.shutdown(); }
    bool running() const { return server_.active(); }

    // One host frame: the server frames that are due, with `cmd`, their messages applied to
    // `client` (and recorded). Ended when the server stopped with an error.
    FrameStatus run_frame(ClientState& client, double frame_time, const MoveCommand& cmd);
    // The view angles the server set (spawn, teleport) since the last call.
    std::optional<std::array<float, 3>> take_set_angles();

    // Starts recording what the client receives from now on: the signon state first.
    std::string start_recording(const std::string& path, const std::array<float, 3>& angles);
    // Ends the recording with a disconnect block; the file's size, 0 when none was made.
    uint64_t stop_recording(const std::array<float, 3>& angles);
    const DemoRecorder& recorder() const { return recorder_; }

    server::Server& server() { return server_; }
    const std::optional<Error>& error() const { return error_; }

  private:
    void level_started();
    bool apply(ClientState& client, std::span<const uint8_t> block,
               const std::array<float, 3>& angles);

    server::Server server_;
    ServerMessageDecoder decoder_;
    protocol::ProtocolState protocol_;
    DemoRecorder recorder_;
    double pending_time_ = 0;  // host time not yet run by the server
    size_t blocks_applied_ = 0;
    bool fresh_level_ = false;  // the spawn messages are waiting to be applied
    std::optional<std::array<float, 3>> set_angles_;
    std::optional<Error> error_;
};

}  // namespace nq
