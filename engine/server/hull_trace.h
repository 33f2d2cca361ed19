// One sweep through one collision hull with the results Quake's server sees (SV_ClipMoveToEntity):
// the hull is placed in the world by an offset, a trace that never leaves solid reports fraction 1
// and the requested end (not trace_hull's fraction 0), and the contents the sweep passed through
// set in_open / in_water. Entity boxes are traced through a six-plane clip hull (BoxHull), as
// Quake does, so boxes and brush models share every rule and every rounding.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>

#include "formats/bsp.h"
#include "vm/vm.h"

namespace nq::server {

using vm::Vec3f;

struct MoveTrace {
    bool all_solid = false;    // never left solid
    bool start_solid = false;  // started in solid (or touched solid before leaving it)
    bool in_open = false;      // passed through empty space
    bool in_water = false;     // passed through liquid (or any other non-solid contents)
    float fraction = 1;        // part of the move made; 1 when nothing was hit or all solid
    Vec3f end_pos{};           // where the move stopped (the requested end when fraction is 1)
    Vec3f plane_normal{};      // of the surface hit, facing the start
    float plane_dist = 0;
    std::optional<uint32_t> entity;  // the edict hit or started in (0 = world), or none
};

// Traces start..end (world space) through hull `hull` of submodel `model` of `bsp`, whose space
// sits at `offset` in the world. `entity` is left empty: the caller knows whose hull it was.
MoveTrace trace_placed_hull(const Bsp& bsp, int hull, size_t model, const Vec3f& offset,
                            const Vec3f& start, const Vec3f& end);

// Quake's box hull: the solid box mins..maxs as a chain of six axial clip planes (x max, x min,
// y max, y min, z max, z min). Points on a max plane are outside, points on a min plane inside.
class BoxHull {
  public:
    static constexpr int kHull = 1;  // the hull index of bsp() that holds the box

    BoxHull();
    // Moves the planes to the box and returns the map holding it (valid until the next set).
    const Bsp& set(const Vec3f& mins, const Vec3f& maxs);

  private:
    Bsp bsp_;
};

}  // namespace nq::server
