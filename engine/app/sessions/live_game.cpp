#include "app/sessions/live_game.h"

#include <cmath>

namespace nq {

namespace {

constexpr int kMaxServerFramesPerHostFrame = 8;  // a long hitch is not caught up all at once

server::UserCmd to_user_cmd(const MoveCommand& m) {
    server::UserCmd cmd;
    cmd.view_angles = m.view_angles;
    cmd.forward_move = m.forward;
    cmd.side_move = m.side;
    cmd.up_move = m.up;
    cmd.buttons = m.buttons;
    cmd.impulse = m.impulse;
    return cmd;
}

}  // namespace

LiveGame::LiveGame(server::ServerHost& host) : server_(host), decoder_("server") {}

std::string LiveGame::start(const std::string& map, const server::ServerSettings& settings,
                            server::SpawnParms parms) {
    const server::SpawnResult result = server_.spawn(map, settings, parms);
    if (!result.error.empty()) return result.error;
    level_started();
    return {};
}

// The server's new level: its signon goes to the client with the next frame.
void LiveGame::level_started() {
    protocol_ = {};
    pending_time_ = 0;
    fresh_level_ = true;
    error_.reset();
}

FrameStatus LiveGame::run_frame(ClientState& client, double frame_time, const MoveCommand& cmd) {
    if (!server_.active()) return FrameStatus::Ended;
    const std::array<float, 3> angles = cmd.view_angles;
    if (fresh_level_) {  // the signon the spawn produced
        fresh_level_ = false;
        for (const std::vector<uint8_t>& block : server_.client_messages()) {
            if (!apply(client, block, angles)) return FrameStatus::Ended;
        }
    }
    pending_time_ += frame_time;
    int frames = 0;
    const server::UserCmd user_cmd = to_user_cmd(cmd);
    while (pending_time_ >= kServerFrameTime && frames < kMaxServerFramesPerHostFrame) {
        pending_time_ -= kServerFrameTime;
        ++frames;
        if (!server_.frame(kServerFrameTime, user_cmd)) {
            error_ = Error{"server", 0, server_.error()};
            return FrameStatus::Ended;
        }
        for (const std::vector<uint8_t>& block : server_.client_messages()) {
            if (!apply(client, block, angles)) return FrameStatus::Ended;
        }
        if (!server_.active()) return FrameStatus::Ended;
    }
    if (frames == kMaxServerFramesPerHostFrame) pending_time_ = 0;
    // Drawn one server frame behind, so entities blend between the last two frames.
    client.set_time(server_.time() - kServerFrameTime + pending_time_);
    // The player's own angles, not blended: the view answers the mouse at once.
    client.set_view_angles({angles[0], angles[1], angles[2]});
    return FrameStatus::Playing;
}

bool LiveGame::apply(ClientState& client, std::span<const uint8_t> block,
                     const std::array<float, 3>& angles) {
    if (auto problem = decoder_.decode(block, blocks_applied_++, 0, protocol_)) {
        error_ = std::move(*problem);
        return false;
    }
    if (recorder_.recording()) recorder_.write_block(angles, block);
    for (const DecodedMessage& m : decoder_.block().messages) {
        if (auto* s = std::get_if<svc::SetAngle>(&m.message)) {
            set_angles_ = std::array<float, 3>{s->angles[0], s->angles[1], s->angles[2]};
        }
        if (auto problem = client.apply(m.message)) {
            error_ = Error{"server", m.offset, *problem};
            return false;
        }
    }
    return true;
}

std::optional<std::array<float, 3>> LiveGame::take_set_angles() {
    std::optional<std::array<float, 3>> a = set_angles_;
    set_angles_.reset();
    return a;
}

std::string LiveGame::start_recording(const std::string& path, const std::array<float, 3>& angles) {
    if (!server_.active()) return "record: no game is running";
    if (std::string why = recorder_.open(path); !why.empty()) return why;
    // A level just started sends its own signon with the next frame; otherwise the client's
    // state so far goes first, so the demo plays from this moment.
    if (!fresh_level_) recorder_.write_block(angles, server_.signon_state());
    return {};
}

uint64_t LiveGame::stop_recording(const std::array<float, 3>& angles) {
    if (!recorder_.recording()) return 0;
    const uint8_t disconnect[] = {protocol::svc_disconnect};
    recorder_.write_block(angles, disconnect);
    return recorder_.close();
}

}  // namespace nq
