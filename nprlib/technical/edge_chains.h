// Fewer, longer edge quads: an entity's edges joined into chains and each chain's nearly
// straight runs drawn as one edge. On a software rasteriser every quad costs two triangle
// set-ups however few pixels it covers, and a distant model's outline is mostly edges a pixel
// or two long; drawn as the straight lines they look like, they cost a fraction.
//   - chains run through vertices where exactly two edges of one kind meet (by welded
//     position, so skin seams do not break them); where more meet, or one, a chain ends;
//   - a run of a chain becomes one edge while every vertex inside it lies within `tolerance`
//     pixels of the straight line between the run's ends. The distance is measured in view
//     space, in units of a pixel at the vertex's depth, so it bounds the error in depth as
//     well as on screen (the edges' depth pull, a few pixels' worth, covers it).
// No GL here; the edge drawer runs it between finding edges and shading their ends.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "technical/alias_edge_mesh.h"

namespace nq::npr::technical {

struct ChainTolerance {
    float pixels = 0.5f;  // largest distance from the straight line, in pixels
    // World units a pixel spans per unit of depth: 2 / (projection[1][1] * viewport height).
    float units_per_pixel_per_depth = 0.0f;
};

class EdgeChains {
  public:
    // Rewrites `edges` (one entity's, MDL vertex indices) with straight runs merged.
    // `representative` maps each MDL vertex to one MDL vertex standing for its welded position
    // (AliasEdgeMesh::seam_representatives); `view` holds the view-space position (GL axes:
    // depth is -z) of every vertex the edges use. Order of the result: chain by chain.
    void simplify(std::vector<FoundEdge>& edges, std::span<const uint32_t> representative,
                  const glm::vec3* view, const ChainTolerance& tolerance);

  private:
    // Per (welded position, kind): the ends there, counted while the stamp is this entity's.
    struct Meeting {
        uint32_t stamp = 0;
        uint32_t count = 0;
        uint32_t first = 0, second = 0;  // slots: edge * 2 + end
    };
    void link_ends(const std::vector<FoundEdge>& edges, std::span<const uint32_t> representative);
    Meeting* meeting(const FoundEdge& edge, uint32_t vertex,
                     std::span<const uint32_t> representative);
    void walk(const std::vector<FoundEdge>& edges, uint32_t edge, uint32_t end);
    void emit_runs(EdgeKind kind, const glm::vec3* view, const ChainTolerance& tolerance);
    bool straight(size_t from, size_t to, const glm::vec3* view,
                  const ChainTolerance& tolerance) const;

    std::vector<Meeting> meetings_;  // by representative * 4 + kind
    uint32_t stamp_ = 0;
    std::vector<int32_t> link_;     // per slot: the slot it continues into, or -1
    std::vector<uint8_t> visited_;  // per edge
    std::vector<uint32_t> points_;  // the chain being walked: MDL vertices
    std::vector<FoundEdge> out_;
};

}  // namespace nq::npr::technical
