#include "app/demo_session.h"

#include "fs/vfs.h"

namespace nq {

namespace {

ModelCache::FileReader vfs_reader(const Vfs* vfs) {
    return [vfs](const std::string& path) -> Result<std::vector<uint8_t>> {
        if (!vfs) return Error{path, 0, "no game data mounted"};
        return vfs->read(path);
    };
}

}  // namespace

DemoSession::DemoSession(const Vfs* vfs, DemoSessionCallbacks callbacks)
    : vfs_(vfs), callbacks_(std::move(callbacks)), level_(vfs_reader(vfs)),
      client_(std::make_unique<ClientState>()) {}

DemoSession::~DemoSession() { stop(); }

std::string DemoSession::start(const std::string& name, DemoMode mode) {
    stop();
    if (!vfs_) return "no game data: cannot play demos (see -basedir and -game)";
    std::string path = name;
    if (!vfs_->exists(path)) path = name + ".dem";
    auto bytes = vfs_->read(path);
    if (!bytes) return "cannot play demo \"" + name + "\": " + bytes.error().message;
    auto player = DemoPlayer::open(bytes.value(), path, mode);
    if (!player) return player.error().to_string();
    client_ = std::make_unique<ClientState>();
    player_.emplace(std::move(player.value()));
    for (const auto& w : player_->warnings()) callbacks_.print(path + ": " + w);
    name_ = name;
    mode_ = mode;
    generation_ = 0;
    paused_ = false;
    return {};
}

void DemoSession::stop() {
    if (!player_ && !level_.loaded()) return;
    if (level_.loaded() && callbacks_.level_unloading) callbacks_.level_unloading();
    level_.clear();
    player_.reset();
    paused_ = false;
}

FrameStatus DemoSession::frame(double frame_time) {
    if (!player_) return FrameStatus::Ended;
    if (paused_) {
        // No time passes (old time = time): the view and the scene see a still instant.
        client_->advance_clock(0);
        return FrameStatus::Playing;
    }
    FrameStatus status = player_->read_frame(*client_, frame_time);
    if (client_->generation() != generation_) {
        generation_ = client_->generation();
        on_new_level();
    }
    if (status == FrameStatus::Playing) client_->prepare_frame(player_->lerp_mode());
    drain_client_text();
    if (status == FrameStatus::Ended && player_->error()) {
        callbacks_.print("demo stopped: " + player_->error()->to_string());
    }
    return status;
}

void DemoSession::on_new_level() {
    if (level_.loaded() && callbacks_.level_unloading) callbacks_.level_unloading();
    auto loaded = level_.load(*client_);
    for (const auto& w : level_.take_warnings()) callbacks_.print("warning: " + w);
    if (!loaded) {
        callbacks_.print("cannot load level: " + loaded.error().to_string());
        return;
    }
    if (callbacks_.level_loaded) callbacks_.level_loaded(level_);
}

void DemoSession::drain_client_text() {
    for (const auto& text : client_->take_console_text()) callbacks_.print(text);
    for (const auto& text : client_->take_center_prints()) {
        if (callbacks_.center_print) callbacks_.center_print(text);
    }
    for (const auto& text : client_->take_stuff_text()) {
        if (callbacks_.stuff_text) callbacks_.stuff_text(text);
    }
}

}  // namespace nq
