#include "server/world.h"

#include <utility>

#include "server/qmath.h"
#include "server/touched_leafs.h"

namespace nq::server {

namespace {

// Quake's current contents (CONTENTS_CURRENT_0 .. CONTENTS_CURRENT_DOWN) are water to the game.
constexpr int32_t kCurrentFirst = -9;
constexpr int32_t kCurrentLast = -14;
constexpr float kMissileHalfSize = 15;  // MOVE_MISSILE's box against monsters

bool boxes_overlap(const Vec3f& amin, const Vec3f& amax, const Vec3f& bmin, const Vec3f& bmax) {
    for (int i = 0; i < 3; ++i) {
        if (amin[i] > bmax[i] || amax[i] < bmin[i]) return false;
    }
    return true;
}

// The brush hull a moving box collides with, chosen by its width as Quake does.
int hull_for_size(const Vec3f& mins, const Vec3f& maxs) {
    const float width = maxs[0] - mins[0];
    if (width < 3) return 0;
    return width <= 32 ? 1 : 2;
}

// A box moving through a brush model at `origin`: the hull's own box stands for the moving one,
// so the model is shifted by the difference between their mins.
MoveTrace trace_brush(const Bsp& bsp, size_t submodel, const Vec3f& origin, const Vec3f& start,
                      const Vec3f& mins, const Vec3f& maxs, const Vec3f& end) {
    const int hull = hull_for_size(mins, maxs);
    const Vec3f offset = vadd(vsub(bsp.hulls[hull].clip_mins, mins), origin);
    return trace_placed_hull(bsp, hull, submodel, offset, start, end);
}

}  // namespace

struct World::MoveClip {
    Vec3f start, end;
    Vec3f mins, maxs;        // the moving box
    Vec3f mins2, maxs2;      // the moving box against monsters
    Vec3f boxmins, boxmaxs;  // everything the move may reach
    MoveKind kind = MoveKind::normal;
    std::optional<uint32_t> pass;
    MoveTrace trace;
};

World::World(vm::Vm& vm, const ProgsLayout& layout)
    : vm_(vm),
      fields_(layout.fields),
      globals_(layout.globals),
      area_(vm.max_edicts()),
      leafs_(vm.max_edicts()) {
    touch_stack_.reserve(vm.max_edicts());
}

void World::set_level(const Bsp* world, std::vector<CollisionModel> models) {
    world_ = world;
    models_ = std::move(models);
    Vec3f mins{}, maxs{};
    if (world && !world->models.empty()) {
        mins = world->models[0].mins;
        maxs = world->models[0].maxs;
    }
    area_.build(mins, maxs);
    for (EntityLeafs& leafs : leafs_) leafs = {};
}

void World::set_model(size_t index, CollisionModel model) {
    if (index >= models_.size()) models_.resize(index + 1);
    models_[index] = model;
}

int32_t World::truncated(uint32_t edict, uint32_t field) const {
    const float f = vm_.field_float(edict, field);
    // C's (int) cast, without its undefined behaviour on NaN and huge values.
    if (!(f > -2147483648.0f && f < 2147483648.0f)) return 0;
    return static_cast<int32_t>(f);
}

bool World::is_free(uint32_t edict) const {
    return pool_ && pool_->is_free(edict);
}

// ---- linking ----

void World::unlink(uint32_t edict) {
    area_.unlink(edict);
}

void World::clear() {
    area_.unlink_all();
    for (EntityLeafs& leafs : leafs_) leafs = {};
}

void World::link(uint32_t edict, bool touch) {
    if (edict >= leafs_.size()) return;
    area_.unlink(edict);
    if (edict == 0 || is_free(edict)) return;

    const Vec3f origin = vm_.field_vector(edict, fields_.origin);
    Vec3f absmin = vadd(origin, vm_.field_vector(edict, fields_.mins));
    Vec3f absmax = vadd(origin, vm_.field_vector(edict, fields_.maxs));
    // Items grow sideways to be picked up off shelves; everything else by the 1 unit a move
    // stops short of what it hits, so boxes that almost touch are still checked.
    const bool item = (truncated(edict, fields_.flags) & qc::kFlItem) != 0;
    for (int i = 0; i < 3; ++i) {
        const float grow = item ? (i < 2 ? 15.0f : 0.0f) : 1.0f;
        absmin[i] -= grow;
        absmax[i] += grow;
    }
    vm_.set_field_vector(edict, fields_.absmin, absmin);
    vm_.set_field_vector(edict, fields_.absmax, absmax);

    EntityLeafs& leafs = leafs_[edict];
    leafs = {};
    if (world_ && truncated(edict, fields_.modelindex) != 0) {
        const TouchedLeafs found = find_touched_leafs(*world_, absmin, absmax, leafs.leafs);
        leafs.count = static_cast<uint8_t>(found.count);
        leafs.complete = found.complete;
    }

    const int32_t solid = truncated(edict, fields_.solid);
    if (solid == qc::kSolidNot) return;
    area_.link(edict, absmin, absmax,
               solid == qc::kSolidTrigger ? AreaTree::kTriggers : AreaTree::kSolids);
    if (touch) touch_triggers(edict);
}

std::span<const int32_t> World::leafs_of(uint32_t edict) const {
    if (edict >= leafs_.size()) return {};
    return std::span<const int32_t>(leafs_[edict].leafs).first(leafs_[edict].count);
}

bool World::leafs_complete(uint32_t edict) const {
    return edict >= leafs_.size() || leafs_[edict].complete;
}

// ---- triggers ----

// Touch functions may relink anything, nest another link(), or free entities, so the triggers
// are gathered first (on a stack each nested call extends and trims back) and each is checked
// again just before its turn.
void World::touch_triggers(uint32_t edict) {
    const size_t base = touch_stack_.size();
    const Vec3f absmin = vm_.field_vector(edict, fields_.absmin);
    const Vec3f absmax = vm_.field_vector(edict, fields_.absmax);
    area_.walk(AreaTree::kTriggers, absmin, absmax, [&](uint32_t trigger) {
        if (trigger != edict &&
            boxes_overlap(absmin, absmax, vm_.field_vector(trigger, fields_.absmin),
                          vm_.field_vector(trigger, fields_.absmax))) {
            touch_stack_.push_back(trigger);
        }
        return true;
    });
    const size_t end = touch_stack_.size();
    for (size_t i = base; i < end && !vm_.error(); ++i) {
        const uint32_t trigger = touch_stack_[i];
        if (touches(edict, trigger)) run_touch(trigger, edict);
    }
    touch_stack_.resize(base);
}

bool World::touches(uint32_t edict, uint32_t trigger) const {
    return trigger != edict && area_.linked(trigger) && !is_free(trigger) &&
           truncated(trigger, fields_.solid) == qc::kSolidTrigger &&
           vm_.field_int(trigger, fields_.touch) != 0 &&
           boxes_overlap(vm_.field_vector(edict, fields_.absmin),
                         vm_.field_vector(edict, fields_.absmax),
                         vm_.field_vector(trigger, fields_.absmin),
                         vm_.field_vector(trigger, fields_.absmax));
}

void World::run_touch(uint32_t trigger, uint32_t edict) {
    const uint32_t old_self = vm_.global_word(globals_.self);
    const uint32_t old_other = vm_.global_word(globals_.other);
    vm_.set_global_word(globals_.self, vm_.entity_value(trigger));
    vm_.set_global_word(globals_.other, vm_.entity_value(edict));
    vm_.execute(vm_.field_int(trigger, fields_.touch));
    vm_.set_global_word(globals_.self, old_self);
    vm_.set_global_word(globals_.other, old_other);
}

// ---- traces ----

const CollisionModel* World::brush_model(uint32_t edict) const {
    if (truncated(edict, fields_.solid) != qc::kSolidBsp) return nullptr;
    const int32_t index = truncated(edict, fields_.modelindex);
    if (index < 0 || static_cast<size_t>(index) >= models_.size()) return nullptr;
    const CollisionModel& model = models_[static_cast<size_t>(index)];
    if (!model.bsp || model.submodel >= model.bsp->models.size()) return nullptr;
    return &model;
}

MoveTrace World::clip_to_world(const Vec3f& start, const Vec3f& mins, const Vec3f& maxs,
                               const Vec3f& end) {
    MoveTrace t;
    t.end_pos = end;
    if (!world_ || world_->models.empty()) return t;
    t = trace_brush(*world_, 0, {0, 0, 0}, start, mins, maxs, end);
    if (t.fraction < 1 || t.start_solid) t.entity = 0;
    return t;
}

// SOLID_BSP entities with a brush model are traced through the model's hulls at their origin
// (never rotated, as in Quake); every other solid entity is its box, grown by the moving box.
MoveTrace World::clip_to_entity(uint32_t edict, const Vec3f& start, const Vec3f& mins,
                                const Vec3f& maxs, const Vec3f& end) {
    const Vec3f origin = vm_.field_vector(edict, fields_.origin);
    MoveTrace t;
    if (const CollisionModel* model = brush_model(edict)) {
        t = trace_brush(*model->bsp, model->submodel, origin, start, mins, maxs, end);
    } else {
        const Bsp& box = box_.set(vsub(vm_.field_vector(edict, fields_.mins), maxs),
                                  vsub(vm_.field_vector(edict, fields_.maxs), mins));
        t = trace_placed_hull(box, BoxHull::kHull, 0, origin, start, end);
    }
    if (t.fraction < 1 || t.start_solid) t.entity = edict;
    return t;
}

// One entity of the area walk; false stops the walk (nothing can change an all-solid trace).
bool World::clip_to_link(MoveClip& clip, uint32_t touch) {
    const int32_t solid = truncated(touch, fields_.solid);
    if (solid == qc::kSolidNot || solid == qc::kSolidTrigger) return true;
    if (clip.pass && touch == *clip.pass) return true;
    if (clip.kind == MoveKind::no_monsters && solid != qc::kSolidBsp) return true;
    if (!boxes_overlap(clip.boxmins, clip.boxmaxs, vm_.field_vector(touch, fields_.absmin),
                       vm_.field_vector(touch, fields_.absmax))) {
        return true;
    }
    // Points never interact with boxes that are not points.
    if (clip.pass && vm_.field_vector(*clip.pass, fields_.size)[0] != 0 &&
        vm_.field_vector(touch, fields_.size)[0] == 0) {
        return true;
    }
    if (clip.trace.all_solid) return false;
    if (clip.pass) {
        // Missiles pass through their shooter, and the shooter through its missiles.
        if (uint32_t(vm_.field_int(touch, fields_.owner)) == vm_.entity_value(*clip.pass) ||
            uint32_t(vm_.field_int(*clip.pass, fields_.owner)) == vm_.entity_value(touch)) {
            return true;
        }
    }
    const bool monster = (truncated(touch, fields_.flags) & qc::kFlMonster) != 0;
    MoveTrace t = clip_to_entity(touch, clip.start, monster ? clip.mins2 : clip.mins,
                                 monster ? clip.maxs2 : clip.maxs, clip.end);
    if (t.all_solid || t.start_solid || t.fraction < clip.trace.fraction) {
        const bool was_start_solid = clip.trace.start_solid;
        t.entity = touch;
        clip.trace = t;
        clip.trace.start_solid = clip.trace.start_solid || was_start_solid;
    }
    return true;
}

MoveTrace World::move(const Vec3f& start, const Vec3f& mins, const Vec3f& maxs, const Vec3f& end,
                      MoveKind kind, uint32_t passedict) {
    MoveClip clip;
    clip.trace = clip_to_world(start, mins, maxs, end);
    clip.start = start;
    clip.end = end;
    clip.mins = mins;
    clip.maxs = maxs;
    clip.kind = kind;
    if (passedict < leafs_.size()) clip.pass = passedict;
    if (kind == MoveKind::missile) {
        clip.mins2 = {-kMissileHalfSize, -kMissileHalfSize, -kMissileHalfSize};
        clip.maxs2 = {kMissileHalfSize, kMissileHalfSize, kMissileHalfSize};
    } else {
        clip.mins2 = mins;
        clip.maxs2 = maxs;
    }
    for (int i = 0; i < 3; ++i) {
        const bool up = end[i] > start[i];
        clip.boxmins[i] = (up ? start[i] : end[i]) + clip.mins2[i] - 1;
        clip.boxmaxs[i] = (up ? end[i] : start[i]) + clip.maxs2[i] + 1;
    }
    area_.walk(AreaTree::kSolids, clip.boxmins, clip.boxmaxs,
               [&](uint32_t touch) { return clip_to_link(clip, touch); });
    return clip.trace;
}

// ---- points ----

int32_t World::point_contents(const Vec3f& p) const {
    if (!world_) return bsp_contents::empty;
    const int32_t contents = nq::point_contents(*world_, 0, p, 0);
    if (contents <= kCurrentFirst && contents >= kCurrentLast) return bsp_contents::water;
    return contents;
}

std::optional<uint32_t> World::test_entity_position(uint32_t edict) {
    if (edict >= leafs_.size()) return std::nullopt;
    const Vec3f origin = vm_.field_vector(edict, fields_.origin);
    const MoveTrace t =
        move(origin, vm_.field_vector(edict, fields_.mins), vm_.field_vector(edict, fields_.maxs),
             origin, MoveKind::normal, edict);
    if (!t.start_solid) return std::nullopt;
    return t.entity.value_or(0);
}

}  // namespace nq::server
