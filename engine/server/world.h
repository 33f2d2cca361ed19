// The server's collision world (Quake's world.c): where every solid and trigger entity is, box
// traces against the map and those entities, trigger touching, point contents, and the map leafs
// each entity touches for the PVS.
//
// Entities are edicts of the VM; the world reads and writes their fields (origin, mins, maxs,
// absmin, absmax, solid, flags, modelindex, owner, touch) through the layout. A bad edict number
// is ignored, never a crash. Storage for every edict is made at construction, so link() and move()
// do not allocate once a level runs.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "formats/bsp.h"
#include "server/area_tree.h"
#include "server/edict_pool.h"
#include "server/hull_trace.h"
#include "server/progs_layout.h"
#include "vm/vm.h"

namespace nq::server {

// Collision geometry for a model index: brush models (world "*N" submodels and .bsp item boxes)
// have a Bsp and a submodel; alias and sprite models have none.
struct CollisionModel {
    const Bsp* bsp = nullptr;
    size_t submodel = 0;
};

enum class MoveKind { normal = 0, no_monsters = 1, missile = 2 };  // QuakeC's MOVE_*

// A passedict that names no edict: move() then skips nothing. (Passing 0 names the world, and
// as in Quake that skips every entity whose owner is the world.)
inline constexpr uint32_t kNoPassEdict = UINT32_MAX;

class World {
  public:
    static constexpr size_t kMaxEntityLeafs = 32;  // Quake's MAX_ENT_LEAFS

    World(vm::Vm& vm, const ProgsLayout& layout);

    // A new level: the world map (model 0's bounds make the area tree) and the collision model
    // per model index (index 0 unused, 1 the world). Unlinks everything.
    void set_level(const Bsp* world, std::vector<CollisionModel> models);
    // Adds or replaces the collision model of one index (models precached while spawning).
    void set_model(size_t index, CollisionModel model);
    // With a pool (reset for the level), free edicts are never linked or touched. Optional.
    void set_edict_pool(const EdictPool* pool) { pool_ = pool; }

    // SV_LinkEdict: unlinks, then (unless it is the world or free) sets absmin/absmax to the box
    // at the origin grown by 1 on every axis (items: by 15 on x and y, 0 on z), finds the map
    // leafs it touches (when it has a model) and, unless SOLID_NOT, links it into the area tree.
    // touch_triggers then runs the touch function of every trigger whose box overlaps its own
    // (self = trigger, other = this edict; the time global is the caller's), restoring self and
    // other afterwards. Touch functions may link, unlink and move entities, even nest link().
    void link(uint32_t edict, bool touch_triggers);
    void unlink(uint32_t edict);
    void clear();  // unlinks everything
    bool linked(uint32_t edict) const { return area_.linked(edict); }

    // SV_Move: the box mins..maxs swept from start to end against the world and every linked
    // solid entity except passedict, the entities it owns and its owner. no_monsters skips all
    // but SOLID_BSP entities; missile uses a -15..15 box against FL_MONSTER entities. The
    // nearest hit wins, ties go to what was tested first (the world, then the area tree's order).
    // As in Quake, an entity the move starts in replaces any earlier result, and start_solid
    // stays set once anything reported it; a move that never leaves solid reports fraction 1.
    MoveTrace move(const Vec3f& start, const Vec3f& mins, const Vec3f& maxs, const Vec3f& end,
                   MoveKind kind, uint32_t passedict);
    // Contents at p in the world's hull 0; the current contents (-9..-14) read as water. Empty
    // when no level is set.
    int32_t point_contents(const Vec3f& p) const;
    // SV_TestEntityPosition: whether the entity's box at its origin is in solid; the blocker
    // (0 = world) or none.
    std::optional<uint32_t> test_entity_position(uint32_t edict);
    // Indices into Bsp::leafs (leaf n is PVS bit n - 1) the edict touched when last linked.
    std::span<const int32_t> leafs_of(uint32_t edict) const;
    // False when it touched more than kMaxEntityLeafs leafs (treat it as visible everywhere).
    bool leafs_complete(uint32_t edict) const;

  private:
    struct EntityLeafs {
        std::array<int32_t, kMaxEntityLeafs> leafs{};
        uint8_t count = 0;
        bool complete = true;
    };
    struct MoveClip;

    MoveTrace clip_to_world(const Vec3f& start, const Vec3f& mins, const Vec3f& maxs,
                            const Vec3f& end);
    MoveTrace clip_to_entity(uint32_t edict, const Vec3f& start, const Vec3f& mins,
                             const Vec3f& maxs, const Vec3f& end);
    bool clip_to_link(MoveClip& clip, uint32_t touch);
    const CollisionModel* brush_model(uint32_t edict) const;
    void touch_triggers(uint32_t edict);
    bool touches(uint32_t edict, uint32_t trigger) const;
    void run_touch(uint32_t trigger, uint32_t edict);
    bool is_free(uint32_t edict) const;
    int32_t truncated(uint32_t edict, uint32_t field) const;  // a float field as an int

    vm::Vm& vm_;
    const FieldOffsets fields_;
    const GlobalOffsets globals_;
    const Bsp* world_ = nullptr;
    std::vector<CollisionModel> models_;
    const EdictPool* pool_ = nullptr;
    AreaTree area_;
    BoxHull box_;
    std::vector<EntityLeafs> leafs_;     // per edict
    std::vector<uint32_t> touch_stack_;  // the triggers to touch, one frame per link()
};

}  // namespace nq::server
