#include "client/demo_player.h"

#include <utility>

#include "formats/message_decoder.h"

namespace nq {

DemoPlayer::DemoPlayer(Demo demo, std::string name, DemoMode mode)
    : demo_(std::move(demo)), name_(std::move(name)), mode_(mode), decoder_(name_) {
    warnings_ = demo_.warnings;
}

Result<DemoPlayer> DemoPlayer::open(std::span<const uint8_t> file, const std::string& name,
                                    DemoMode mode) {
    auto demo = parse_dem(file, name);
    if (!demo) return demo.error();
    return DemoPlayer(std::move(demo.value()), name, mode);
}

LerpMode DemoPlayer::lerp_mode() const {
    return mode_ == DemoMode::TimeDemo ? LerpMode::Snap : LerpMode::Interpolate;
}

FrameStatus DemoPlayer::run_frame(ClientState& client, double frame_time) {
    if (read_frame(client, frame_time) == FrameStatus::Ended) return FrameStatus::Ended;
    client.prepare_frame(lerp_mode());
    return FrameStatus::Playing;
}

FrameStatus DemoPlayer::read_frame(ClientState& client, double frame_time) {
    if (ended_) return FrameStatus::Ended;
    client.advance_clock(frame_time);
    bool read_this_frame = false;
    while (block_due(client, read_this_frame)) {
        if (!read_block(client)) return FrameStatus::Ended;
    }
    ++frames_;
    return FrameStatus::Playing;
}

bool DemoPlayer::block_due(const ClientState& client, bool& read_this_frame) const {
    if (!client.signed_on()) return true;  // connection messages are read all at once
    if (mode_ == DemoMode::TimeDemo) {
        if (read_this_frame) return false;
        read_this_frame = true;
        return true;
    }
    return client.time() > client.message_time(0);
}

bool DemoPlayer::read_block(ClientState& client) {
    if (next_block_ >= demo_.blocks.size()) {
        end(std::nullopt);
        return false;
    }
    const size_t index = next_block_++;
    const DemoBlock& block = demo_.blocks[index];
    if (auto error = decoder_.decode(block.message, index, block.message_offset(), protocol_)) {
        end(std::move(error));
        return false;
    }
    DecodedBlock& decoded = decoder_.block();
    for (std::string& w : decoded.warnings) warnings_.push_back(std::move(w));
    client.receive_block_angles(block.view_angles);
    for (const DecodedMessage& m : decoded.messages) {
        if (auto problem = client.apply(m.message)) {
            std::string where = "block " + std::to_string(index) + ": ";
            end(Error{name_, block.message_offset() + m.offset, where + *problem});
            return false;
        }
        if (client.disconnected()) {
            end(std::nullopt);  // the server (or the recording) ended here
            return false;
        }
    }
    return true;
}

void DemoPlayer::end(std::optional<Error> error) {
    ended_ = true;
    error_ = std::move(error);
}

}  // namespace nq
