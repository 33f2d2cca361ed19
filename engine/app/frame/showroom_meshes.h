// Procedural meshes for the showroom: closed, consistently wound triangle meshes with shared
// vertices (so adjacency, silhouettes and creases are well defined). Outward faces are wound
// counter-clockwise in a right-handed frame; the alias-model builder turns that into Quake's
// clockwise convention.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace nq::showroom {

struct Mesh {
    std::string name;
    std::vector<std::array<float, 3>> positions;
    std::vector<std::array<int, 3>> triangles;
};

// An axis-aligned cube of edge `size` centred on the origin: 8 vertices, 12 triangles.
Mesh make_cube(float size);
// An L-shaped step: a block of `size` x `size` x size/2 with a size/2 cube on its back half.
// Its inner edge (where the riser meets the lower tread) is a concave crease (a valley).
Mesh make_step(float size);
// A UV sphere of `radius` with `rings` latitude bands and `segments` longitude segments.
Mesh make_sphere(float radius, int rings, int segments);
// A torus around +Z: major radius `major`, tube radius `minor`.
Mesh make_torus(float major, float minor, int rings, int segments);

}  // namespace nq::showroom
