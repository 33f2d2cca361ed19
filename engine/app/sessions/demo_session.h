// A demo being played: the demo player, the client state it feeds, and the level (map and
// models) the client's precache list names. When the demo changes map, the level is reloaded
// between the two callbacks so the renderer can drop and re-register its models.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "app/sessions/level.h"
#include "app/sessions/live_game.h"
#include "client/demo_player.h"

namespace nq {

class Vfs;

struct DemoSessionCallbacks {
    std::function<void()> level_unloading;        // models are about to be freed
    std::function<void(Level&)> level_loaded;     // register the new models
    std::function<void(Level&)> level_restarted;  // the same map again: models kept
    std::function<void(std::string_view)> print;  // console text, warnings
    std::function<void(std::string_view)> center_print;
    std::function<void(std::string_view)> stuff_text;  // commands the server sent
};

class DemoSession {
  public:
    DemoSession(const Vfs* vfs, DemoSessionCallbacks callbacks);
    ~DemoSession();

    // Where recorded demos are written (<userdir>/<game>): searched before the game data.
    void set_user_dir(std::string dir) { user_dir_ = std::move(dir); }
    // Opens "<name>" or "<name>.dem" from the user dir or through the VFS; "" on success,
    // else the reason.
    std::string start(const std::string& name, DemoMode mode);
    // Whether start() would find the demo's file (it may still fail to parse).
    bool exists(const std::string& name) const;
    // Plays the game instead: `game` has just started a level; its messages feed the client
    // the way a demo's blocks do. The session keeps `game` until stop().
    void start_game(std::unique_ptr<LiveGame> game, const std::string& map);
    void stop();
    bool active() const { return player_.has_value() || live_ != nullptr; }
    LiveGame* live() { return live_.get(); }
    const LiveGame* live() const { return live_.get(); }

    // A paused demo reads nothing and its clock stands still, so the same instant is drawn
    // again and again. Only a playing demo can be paused; starting or stopping one unpauses.
    void set_paused(bool paused) { paused_ = paused && active(); }
    bool paused() const { return paused_; }

    // Plays one host frame (or, paused, holds the current one); returns Ended when the demo
    // finished (or failed) in it.
    // In a game, `cmd` is the player's command for the frame (required then).
    FrameStatus frame(double frame_time, const MoveCommand* cmd = nullptr);

    // Why the session ended early ("" while it plays or when it ended as recorded): a message
    // it could not decode, or a level it could not load (nothing could be drawn).
    const std::string& failure() const { return failure_; }

    const std::string& name() const { return name_; }
    // +1 for every demo or game started: what listens to the client knows a new one began.
    uint32_t starts() const { return starts_; }
    DemoMode mode() const { return mode_; }
    ClientState& client() { return *client_; }
    Level& level() { return level_; }
    const DemoPlayer* player() const { return player_ ? &*player_ : nullptr; }
    bool level_ready() const { return level_.loaded() && client_ && client_->signed_on(); }

  private:
    bool on_new_level();  // false when the level cannot load
    void drain_client_text();

    const Vfs* vfs_;
    DemoSessionCallbacks callbacks_;
    Level level_;
    std::unique_ptr<ClientState> client_;
    std::optional<DemoPlayer> player_;
    std::unique_ptr<LiveGame> live_;
    std::string name_;
    DemoMode mode_ = DemoMode::Playback;
    uint32_t generation_ = 0;
    uint32_t starts_ = 0;
    bool paused_ = false;
    std::string failure_;
    std::string console_line_;  // printed text not yet ended by a newline
    std::string user_dir_;
};

}  // namespace nq
