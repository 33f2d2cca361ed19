// Counting a triangle set's edges by how many triangles use them and in which directions:
// the figures `mdltool adjacency` reports for the welded soup, the final mesh and the paper's
// per-frame hashing alike.
#pragma once

#include <array>
#include <cstdint>
#include <span>

namespace nq::npr::adjacency {

struct EdgeCensus {
    uint32_t edges = 0;         // distinct undirected edges
    uint32_t zero_length = 0;   // both ends the same point (only degenerate triangles make them)
    uint32_t boundary = 0;      // used by one triangle
    uint32_t manifold = 0;      // used by exactly two triangles
    uint32_t consistent = 0;    // manifold, and the two traverse it in opposite directions
    uint32_t non_manifold = 0;  // used by three or more triangles

    // Tallies one distinct edge from the number of triangles using it in each direction.
    void add_edge(uint32_t forward_uses, uint32_t backward_uses, bool is_zero_length);
    // Share of all edges that are manifold and consistently oriented (0 for no edges).
    double consistent_share() const { return edges ? double(consistent) / double(edges) : 0.0; }
    bool operator==(const EdgeCensus&) const = default;
};

// Edges of triangles given as vertex indices, keyed by index pairs.
EdgeCensus census_of_indexed_triangles(std::span<const std::array<uint32_t, 3>> triangles);

}  // namespace nq::npr::adjacency
