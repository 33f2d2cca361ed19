// A level for the physics tests: a real LibreQuake map in the collision world, the QuakeC hooks
// of tests/qc/physics (every function counts its calls in a global), an edict pool with one
// client slot, and sinks that record sounds and console messages.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "common/file_io.h"
#include "formats/bsp.h"
#include "server/edict_pool.h"
#include "server/game_state.h"
#include "server/physics.h"
#include "server/progs_layout.h"
#include "server/server_host.h"
#include "server/world.h"
#include "support/test_data.h"
#include "vm/vm.h"

namespace nq::server::test {

using vm::Vec3f;

struct RecordedSound {
    uint32_t edict;
    std::string sample;
};

class SoundRecorder : public SoundSink {
  public:
    void start_sound(uint32_t edict, int, std::string_view sample, float, float) override {
        sounds.push_back({edict, std::string(sample)});
    }
    std::vector<RecordedSound> sounds;
};

class HostRecorder : public ServerHost {
  public:
    std::optional<std::vector<uint8_t>> read_file(std::string_view) override { return {}; }
    void print(std::string_view text) override { printed += text; }
    void debug_print(std::string_view text) override { debug += text; }
    float cvar_value(std::string_view) override { return 0; }
    std::string cvar_string(std::string_view) override { return {}; }
    void set_cvar(std::string_view, std::string_view) override {}
    void add_command(std::string_view) override {}
    std::string printed, debug;
};

inline std::unique_ptr<Bsp> load_map(const std::string& name) {
    const std::string path = nq::test::lq1_dir() + "/maps/" + name;
    auto bytes = read_file(path);
    if (!bytes) throw std::runtime_error("cannot read " + path);
    auto bsp = parse_bsp(*bytes, path);
    if (!bsp) throw std::runtime_error(bsp.error().to_string());
    return std::make_unique<Bsp>(std::move(*bsp));
}

inline std::unique_ptr<vm::Vm> load_physics_progs() {
    const std::string path = std::string(NQ_QC_DIR) + "/physics.dat";
    auto bytes = read_file(path);
    if (!bytes) throw std::runtime_error("missing " + path);
    auto progs = vm::parse_progs(*bytes, "physics.dat");
    if (!progs) throw std::runtime_error(progs.error().to_string());
    return std::make_unique<vm::Vm>(std::move(*progs));
}

inline ProgsLayout layout_of(const vm::Vm& vm) {
    auto layout = resolve_layout(vm.progs());
    if (!layout) throw std::runtime_error(layout.error().to_string());
    return *layout;
}

class PhysicsLevel {
  public:
    static constexpr float kFrame = 1.0f / 72;
    static constexpr uint32_t kPlayer = 1;

    explicit PhysicsLevel(const std::string& map)
        : bsp(load_map(map)),
          vm_(load_physics_progs()),
          layout(layout_of(*vm_)),
          world(*vm_, layout),
          game{*vm_, layout, world, edicts, PhysicsSettings{}} {
        edicts.reset(*vm_, 1);
        world.set_edict_pool(&edicts);
        // Model index 1 is the map, 2.. its brush entities (*1, *2, ...), as precached.
        std::vector<CollisionModel> models(bsp->models.size() + 1);
        for (size_t i = 0; i < bsp->models.size(); ++i) models[i + 1] = {bsp.get(), i};
        world.set_level(bsp.get(), std::move(models));
        const FieldOffsets& f = layout.fields;
        vm().set_field_float(0, f.modelindex, 1);
        vm().set_field_float(0, f.solid, qc::kSolidBsp);
        vm().set_field_float(0, f.movetype, qc::kMovePush);
        game.sounds = &sounds;
        game.time = 1;
        game.frame_time = kFrame;
        context.host = &host;
    }

    vm::Vm& vm() { return *vm_; }
    const FieldOffsets& f() const { return layout.fields; }

    uint32_t spawn() {
        auto e = edicts.alloc(vm(), game.time);
        if (!e) throw std::runtime_error("no free edict");
        return *e;
    }

    // A box entity linked at `origin`.
    uint32_t spawn_box(const Vec3f& origin, const Vec3f& mins, const Vec3f& maxs, int movetype,
                       int solid) {
        const uint32_t e = spawn();
        vm().set_field_vector(e, f().origin, origin);
        vm().set_field_vector(e, f().mins, mins);
        vm().set_field_vector(e, f().maxs, maxs);
        vm().set_field_float(e, f().movetype, float(movetype));
        vm().set_field_float(e, f().solid, float(solid));
        world.link(e, false);
        return e;
    }

    // The player in edict 1, standing at `origin` (Quake's player box).
    void place_player(const Vec3f& origin, float yaw = 0) {
        const uint32_t e = kPlayer;
        vm().set_field_vector(e, f().origin, origin);
        vm().set_field_vector(e, f().mins, {-16, -16, -24});
        vm().set_field_vector(e, f().maxs, {16, 16, 32});
        vm().set_field_vector(e, f().view_ofs, {0, 0, 22});
        vm().set_field_vector(e, f().angles, {0, yaw, 0});
        vm().set_field_vector(e, f().v_angle, {0, yaw, 0});
        vm().set_field_float(e, f().movetype, qc::kMoveWalk);
        vm().set_field_float(e, f().solid, qc::kSolidSlideBox);
        vm().set_field_float(e, f().health, 100);
        vm().set_field_float(e, f().flags, qc::kFlClient | qc::kFlOnGround);
        world.link(e, false);
    }

    bool frame() {
        const uint8_t spawned[] = {player_spawned};
        const bool ok = run_physics(game, spawned, context);
        game.time += game.frame_time;
        return ok;
    }

    float global(const char* name) {
        const vm::Def* def = vm().progs().find_global(name);
        if (!def) throw std::runtime_error(std::string("no global ") + name);
        return vm().global_float(def->offset);
    }
    uint32_t global_edict(const char* name) {
        const vm::Def* def = vm().progs().find_global(name);
        if (!def) throw std::runtime_error(std::string("no global ") + name);
        return vm().edict_of(vm().global_word(def->offset)).value_or(UINT32_MAX);
    }
    int32_t function(const char* name) { return vm().progs().find_function(name); }

    Vec3f origin(uint32_t e) { return vm().field_vector(e, f().origin); }
    Vec3f velocity(uint32_t e) { return vm().field_vector(e, f().velocity); }
    int flags(uint32_t e) { return int(vm().field_float(e, f().flags)); }

    std::unique_ptr<Bsp> bsp;

  private:
    std::unique_ptr<vm::Vm> vm_;

  public:
    ProgsLayout layout;
    World world;
    EdictPool edicts;
    GameState game;
    SoundRecorder sounds;
    HostRecorder host;
    PhysicsContext context;
    uint8_t player_spawned = 0;
};

}  // namespace nq::server::test
