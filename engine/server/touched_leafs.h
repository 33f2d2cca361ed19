// The world leafs an entity's box touches (Quake's SV_FindTouchedLeafs): the server sends an
// entity to a client only when one of them is in the client's PVS.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "formats/bsp.h"
#include "vm/vm.h"

namespace nq::server {

struct TouchedLeafs {
    size_t count = 0;      // leafs written to the output
    bool complete = true;  // false when more leafs touched the box than the output holds
};

// Writes the indices (into Bsp::leafs, so leaf n is PVS bit n - 1) of the non-solid leafs of the
// world's node tree that the box mins..maxs touches, in tree order, up to out.size() of them.
TouchedLeafs find_touched_leafs(const Bsp& world, const vm::Vec3f& mins, const vm::Vec3f& maxs,
                                std::span<int32_t> out);

}  // namespace nq::server
