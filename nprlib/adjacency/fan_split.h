// Vertices that join several separate fans of faces (two cones touching at their tips, the
// corner of a fin after its edge was split) are accepted by OpenMesh but are not manifold:
// such a vertex gets one copy per fan. Two faces around a vertex are in the same fan when they
// share an edge at that vertex.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace nq::npr::adjacency {

struct FanSplit {
    std::vector<std::array<uint32_t, 3>> faces;  // the faces with split corners renumbered
    std::vector<uint32_t> origin;                // per vertex after the split: its vertex before
    uint32_t extra_vertices = 0;                 // copies added (0: nothing changed)
};

FanSplit split_vertex_fans(std::span<const std::array<uint32_t, 3>> faces, uint32_t num_vertices);

}  // namespace nq::npr::adjacency
