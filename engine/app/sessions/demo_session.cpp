#include "app/sessions/demo_session.h"

#include <filesystem>

#include "common/file_io.h"
#include "formats/dem.h"
#include "fs/vfs.h"

namespace nq {

namespace {

ModelCache::FileReader vfs_reader(const Vfs* vfs) {
    return [vfs](const std::string& path) -> Result<std::vector<uint8_t>> {
        if (!vfs) return Error{path, 0, "no game data mounted"};
        return vfs->read(path);
    };
}

// Playback forgives a recording cut mid-block (many real demos are); a timedemo is a
// measurement of the whole recording, so a cut one is refused rather than timed in part.
Result<DemoPlayer> open_player(std::span<const uint8_t> bytes, const std::string& path,
                               DemoMode mode) {
    DemParseOptions options;
    options.allow_truncated_tail = mode != DemoMode::TimeDemo;
    auto demo = parse_dem(bytes, path, options);
    if (!demo) return demo.error();
    return DemoPlayer(std::move(demo.value()), path, mode);
}

// Every demo starts from the same random stream (particle spread, light flicker, animation
// phases), so two timedemos of one demo draw the same frames.
constexpr uint64_t kDemoRandomSeed = 1;

std::unique_ptr<ClientState> seeded_client() {
    ClientSettings settings;
    settings.random_seed = kDemoRandomSeed;
    return std::make_unique<ClientState>(settings);
}

}  // namespace

DemoSession::DemoSession(const Vfs* vfs, DemoSessionCallbacks callbacks)
    : vfs_(vfs),
      callbacks_(std::move(callbacks)),
      level_(vfs_reader(vfs)),
      client_(std::make_unique<ClientState>()) {}

DemoSession::~DemoSession() {
    stop();
}

bool DemoSession::exists(const std::string& name) const {
    if (!vfs_ || name.empty() || name.find("..") != std::string::npos) return false;
    for (const std::string& candidate : {name, name + ".dem"}) {
        std::error_code ec;
        if (!user_dir_.empty() &&
            std::filesystem::is_regular_file(user_dir_ + "/" + candidate, ec)) {
            return true;
        }
        if (vfs_->exists(candidate)) return true;
    }
    return false;
}

std::string DemoSession::start(const std::string& name, DemoMode mode) {
    stop();
    if (!vfs_) return "no game data: cannot play demos (see -basedir and -game)";
    std::string path = name;
    std::optional<std::vector<uint8_t>> bytes;
    if (!user_dir_.empty() && name.find("..") == std::string::npos) {
        for (const std::string& candidate : {name, name + ".dem"}) {
            auto file = read_file(user_dir_ + "/" + candidate);
            if (!file) continue;
            bytes = std::move(file.value());
            path = candidate;
            break;
        }
    }
    if (!bytes) {
        if (!vfs_->exists(path)) path = name + ".dem";
        auto read = vfs_->read(path);
        if (!read) return "cannot play demo \"" + name + "\": " + read.error().message;
        bytes = std::move(read.value());
    }
    auto player = open_player(*bytes, path, mode);
    if (!player) return player.error().to_string();
    client_ = seeded_client();
    player_.emplace(std::move(player.value()));
    for (const auto& w : player_->warnings()) callbacks_.print(path + ": " + w);
    name_ = name;
    mode_ = mode;
    generation_ = 0;
    ++starts_;
    paused_ = false;
    failure_.clear();
    return {};
}

void DemoSession::start_game(std::unique_ptr<LiveGame> game, const std::string& map) {
    stop();
    client_ = std::make_unique<ClientState>();
    live_ = std::move(game);
    name_ = map;
    mode_ = DemoMode::Playback;
    generation_ = 0;
    ++starts_;
    paused_ = false;
    failure_.clear();
}

void DemoSession::stop() {
    if (!player_ && !live_ && !level_.loaded()) return;
    if (level_.loaded() && callbacks_.level_unloading) callbacks_.level_unloading();
    level_.clear();
    player_.reset();
    live_.reset();
    paused_ = false;
}

FrameStatus DemoSession::frame(double frame_time, const MoveCommand* cmd) {
    if (!player_ && !live_) return FrameStatus::Ended;
    if (paused_) {
        // No time passes (old time = time): the view and the scene see a still instant.
        client_->advance_clock(0);
        return FrameStatus::Playing;
    }
    const MoveCommand no_input;
    FrameStatus status = live_ ? live_->run_frame(*client_, frame_time, cmd ? *cmd : no_input)
                               : player_->read_frame(*client_, frame_time);
    if (client_->generation() != generation_) {
        generation_ = client_->generation();
        if (!on_new_level()) status = FrameStatus::Ended;
    }
    if (status == FrameStatus::Playing) {
        client_->prepare_frame(live_ ? LerpMode::Interpolate : player_->lerp_mode());
    }
    drain_client_text();
    if (status == FrameStatus::Ended && failure_.empty()) {
        const std::optional<Error>& error = live_ ? live_->error() : player_->error();
        if (error) failure_ = error->to_string();
        if (error) callbacks_.print((live_ ? "game stopped: " : "demo stopped: ") + failure_);
    }
    return status;
}

bool DemoSession::on_new_level() {
    if (level_.holds(client_->model_names())) {
        level_.reattach(*client_);
        if (callbacks_.level_restarted) callbacks_.level_restarted(level_);
        return true;
    }
    if (level_.loaded() && callbacks_.level_unloading) callbacks_.level_unloading();
    auto loaded = level_.load(*client_);
    for (const auto& w : level_.take_warnings()) callbacks_.print("warning: " + w);
    if (!loaded) {
        failure_ = "cannot load level: " + loaded.error().to_string();
        callbacks_.print(failure_);
        return false;
    }
    if (callbacks_.level_loaded) callbacks_.level_loaded(level_);
    return true;
}

void DemoSession::drain_client_text() {
    // svc_print pieces make lines together ("player" + " entered the game\n"): print whole
    // lines only.
    for (const auto& text : client_->take_console_text()) {
        console_line_ += text;
        for (size_t end; (end = console_line_.find('\n')) != std::string::npos;) {
            callbacks_.print(std::string_view(console_line_).substr(0, end));
            console_line_.erase(0, end + 1);
        }
    }
    for (const auto& text : client_->take_center_prints()) {
        if (callbacks_.center_print) callbacks_.center_print(text);
    }
    for (const auto& text : client_->take_stuff_text()) {
        if (callbacks_.stuff_text) callbacks_.stuff_text(text);
    }
}

}  // namespace nq
