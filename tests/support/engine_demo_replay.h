// Replaying a demo in-process the way the engine's timedemo does (one block per frame, the
// level loaded on every new serverinfo, the view computed once the level is ready), so an
// engine test can know what the engine binary had on screen at a given demo frame.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <optional>
#include <string>

#include "app/sessions/level.h"
#include "client/client_state.h"
#include "client/demo_player.h"
#include "client/view.h"
#include "client/visible_entities.h"
#include "formats/bsp.h"
#include "fs/vfs.h"
#include "render/view_transform.h"
#include "support/engine_output_checks.h"
#include "support/shared_engine_run.h"
#include "support/test_data.h"

namespace nq::test {

// The LibreQuake game as the engine mounts it with -basedir data_root() -game lq1.
inline Vfs mount_lq1() {
    auto vfs = Vfs::mount(VfsConfig::for_game(data_root(), "lq1"));
    if (!vfs) throw std::runtime_error("cannot mount lq1: " + vfs.error().to_string());
    return std::move(vfs.value());
}

inline std::vector<uint8_t> read_game_file(const Vfs& vfs, const std::string& path) {
    auto bytes = vfs.read(path);
    if (!bytes) throw std::runtime_error(bytes.error().to_string());
    return std::move(bytes.value());
}

// What `timedemo <file>` reports as "N frames": every frame that played, less the first
// (whose time includes loading). Counted with a bare client: frame pacing needs no models.
inline uint64_t timedemo_frame_count(const Vfs& vfs, const std::string& file) {
    auto player = DemoPlayer::open(read_game_file(vfs, file), file, DemoMode::TimeDemo);
    if (!player) throw std::runtime_error(player.error().to_string());
    ClientState client;
    while (player->run_frame(client, 0.01) == FrameStatus::Playing) {
    }
    if (player->error()) throw std::runtime_error(player->error()->to_string());
    return player->timedemo_frames();
}

// An alias entity's blended pose in the world, as the plugins draw it (empty when a pose is out
// of range).
inline std::vector<glm::vec3> blended_world_vertices(const nqr_alias_model& a,
                                                     const nqr_entity& e) {
    const glm::mat4 model = load_matrix(e.model_matrix);
    std::vector<glm::vec3> out;
    if (e.pose0 >= a.num_poses || e.pose1 >= a.num_poses) return out;
    for (uint32_t v = 0; v < a.num_vertices; ++v) {
        const nqr_alias_vertex& p0 = a.poses[size_t(e.pose0) * a.num_vertices + v];
        const nqr_alias_vertex& p1 = a.poses[size_t(e.pose1) * a.num_vertices + v];
        glm::vec3 local;
        for (int c = 0; c < 3; ++c) {
            const float blended = p0.v[c] * (1.0f - e.lerp) + p1.v[c] * e.lerp;
            local[c] = a.scale[c] * blended + a.origin[c];
        }
        out.emplace_back(model * glm::vec4(local, 1.0f));
    }
    return out;
}

// `vfs` must outlive the replay (the level reads its models through it).
class DemoReplay {
  public:
    DemoReplay(const Vfs& vfs, const std::string& file)
        : level_([&vfs](const std::string& path) { return vfs.read(path); }) {
        auto player = DemoPlayer::open(read_game_file(vfs, file), file, DemoMode::TimeDemo);
        if (!player) throw std::runtime_error(player.error().to_string());
        player_.emplace(std::move(player.value()));
    }

    // Plays until `frame` frames have played: the state the engine renders in the frame in
    // which `demo_at frame` fires (the screenshot it schedules reads that frame back). False
    // if the demo ends first.
    bool play_to(uint64_t frame) {
        while (player_->frames() < frame) {
            if (!step()) return false;
        }
        return ready_;
    }

    const ClientState& client() const { return client_; }
    const Level& level() const { return level_; }
    Level& level() { return level_; }
    const ViewResult& view() const { return view_; }
    uint64_t frames() const { return player_->frames(); }

    // The entities the engine would consider drawing this frame (before its culling).
    const VisibleEntityList& visible_entities() {
        collect_visible_entities(client_, view_, visible_);
        return visible_;
    }

    // The alias model data behind a client model index, or null (brush, sprite, placeholder).
    const Mdl* alias_mdl(int model_index) const {
        const RenderModel* model = level_.models().get(level_.model_id(model_index));
        if (!model || model->placeholder() || !model->alias_data()) return nullptr;
        return &model->alias_data()->mdl();
    }

    // Whether the straight line between two points crosses no solid world.
    bool line_of_sight(const Vec3& from, const Vec3& to) const {
        const Bsp* bsp = level_.world_bsp();
        if (!bsp) return false;
        BspTrace t = trace_hull(*bsp, 0, {from[0], from[1], from[2]}, {to[0], to[1], to[2]});
        return t.fraction >= 1.0f && !t.start_solid;
    }

  private:
    static int contents_at(void* user, const Vec3& p) {
        const Bsp* bsp = static_cast<const Bsp*>(user);
        return bsp ? point_contents(*bsp, 0, {p[0], p[1], p[2]}) : 0;
    }

    // One engine frame, in the engine's order (DemoSession::frame, then Engine::render_demo).
    bool step() {
        FrameStatus status = player_->read_frame(client_, 0.01);
        if (client_.generation() != generation_) {
            generation_ = client_.generation();
            auto loaded = level_.load(client_);
            if (!loaded) throw std::runtime_error(loaded.error().to_string());
        }
        if (status == FrameStatus::Ended) return false;
        client_.prepare_frame(player_->lerp_mode());
        ready_ = level_.loaded() && client_.signed_on();
        if (ready_) {
            ViewSettings settings;
            settings.contents_at = &contents_at;
            settings.contents_user = const_cast<Bsp*>(level_.world_bsp());
            view_ = compute_view(client_, view_state_, settings);
        }
        return true;
    }

    Level level_;
    ClientState client_;
    std::optional<DemoPlayer> player_;
    uint32_t generation_ = 0;
    bool ready_ = false;
    ViewState view_state_;
    ViewResult view_;
    VisibleEntityList visible_;
};

// The run ended cleanly with one timedemo line counting every frame of `demo_file` (as an
// in-process replay counts them).
inline void expect_whole_timedemo(const SharedRun& run, const std::string& demo_file) {
    expect_clean_exit(run.result);
    const auto lines = timedemo_lines(run.result.out);
    ASSERT_EQ(lines.size(), 1u) << run.result.out;
    Vfs vfs = mount_lq1();
    EXPECT_EQ(lines[0].frames, timedemo_frame_count(vfs, demo_file));
}

}  // namespace nq::test
