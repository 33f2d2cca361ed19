// Plays a recorded demo into a ClientState the way Quake's client reads it:
//  - until the client is signed on (the first entity update after signon stage 3), every
//    block is read at once, in the same frame;
//  - playback: afterwards a block is read only when the client clock has passed the server
//    time of the last message received (so the demo plays at its recorded speed);
//  - timedemo: afterwards exactly one block is read per frame, and the client clock jumps to
//    each block's server time (everything renders as fast as possible, nothing blends).
// Playback ends at the end of the file or at svc_disconnect; the frame in which it ends is not
// a played frame. A demo that changes (or restarts) the map mid-way brings a new
// svc_serverinfo: the client state starts afresh and its generation() increments.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "client/client_state.h"
#include "common/error.h"
#include "common/result.h"
#include "formats/dem.h"
#include "formats/message_decoder.h"
#include "formats/protocol.h"

namespace nq {

enum class DemoMode { Playback, TimeDemo };

enum class FrameStatus {
    Playing,  // the frame has fresh state to render
    Ended,    // end of demo (or an error): nothing more to render
};

class DemoPlayer {
  public:
    DemoPlayer(Demo demo, std::string name, DemoMode mode);
    static Result<DemoPlayer> open(std::span<const uint8_t> file, const std::string& name,
                                   DemoMode mode);

    // One host frame: advances the client clock by frame_time, reads the blocks that are due,
    // then prepares the client's frame (interpolation, effects). The first step alone is
    // read_frame(); prepare the client yourself after it to time the steps separately.
    FrameStatus run_frame(ClientState& client, double frame_time);
    FrameStatus read_frame(ClientState& client, double frame_time);
    LerpMode lerp_mode() const;

    bool ended() const { return ended_; }
    const std::optional<Error>& error() const { return error_; }  // why it ended early
    const std::vector<std::string>& warnings() const { return warnings_; }

    size_t blocks_read() const { return next_block_; }
    size_t block_count() const { return demo_.blocks.size(); }
    // Frames played (each rendered a fresh state), and what timedemo reports: all but the
    // first, whose time includes loading.
    uint64_t frames() const { return frames_; }
    uint64_t timedemo_frames() const { return frames_ > 0 ? frames_ - 1 : 0; }
    DemoMode mode() const { return mode_; }
    const Demo& demo() const { return demo_; }

  private:
    bool block_due(const ClientState& client, bool& read_this_frame) const;
    bool read_block(ClientState& client);  // false when playback ended
    void end(std::optional<Error> error);

    Demo demo_;
    std::string name_;
    DemoMode mode_;
    protocol::ProtocolState protocol_;
    ServerMessageDecoder decoder_;  // its storage is reused block after block
    size_t next_block_ = 0;
    uint64_t frames_ = 0;
    bool ended_ = false;
    std::optional<Error> error_;
    std::vector<std::string> warnings_;
};

}  // namespace nq
