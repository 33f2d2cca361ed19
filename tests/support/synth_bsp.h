// A writer for small BSP maps in BSP29, BSP2 and 2PSB layout: test fixtures and fuzz seeds.
// SynthBsp holds format-independent records with wide integer fields, so tests can store any
// value (out of range, negative) and see how the parser reacts; write_bsp() truncates each field
// to the width the chosen format gives it.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "formats/bsp.h"
#include "support/seed_file.h"

namespace nq::test {

struct SynthBsp {
    using Vec3 = std::array<float, 3>;
    struct Plane {
        Vec3 normal{};
        float dist = 0;
        int32_t type = 0;
    };
    struct Texture {
        std::string name;
        uint32_t width = 16;
        uint32_t height = 16;
        bool missing = false;  // written as miptex offset -1
    };
    struct Texinfo {
        std::array<std::array<float, 4>, 2> vecs{};
        int32_t miptex = 0;
        uint32_t flags = 0;
    };
    struct Face {
        int64_t plane = 0, side = 0, first_surfedge = 0, num_surfedges = 0, texinfo = 0;
        std::array<uint8_t, 4> styles{0, 255, 255, 255};
        int32_t light_offset = -1;
    };
    // Children: >= 0 node/clipnode index; < 0 leaf -(child + 1) (nodes) or contents (clipnodes).
    // BSP29 writes the low 16 bits, which is how the format encodes negative children.
    struct Node {
        int64_t plane = 0;
        std::array<int64_t, 2> children{};
        Vec3 mins{}, maxs{};
        int64_t first_face = 0, num_faces = 0;
    };
    struct Leaf {
        int32_t contents = -1;
        int32_t vis_offset = -1;
        Vec3 mins{}, maxs{};
        int64_t first_marksurface = 0, num_marksurfaces = 0;
        std::array<uint8_t, 4> ambient{};
    };
    struct ClipNode {
        int64_t plane = 0;
        std::array<int64_t, 2> children{};
    };
    struct Model {
        Vec3 mins{}, maxs{}, origin{};
        std::array<int32_t, 4> headnodes{};
        int32_t visleafs = 0, first_face = 0, num_faces = 0;
    };

    std::string entities;  // written with a terminating NUL
    std::vector<Plane> planes;
    std::vector<Texture> textures;  // pixels from synth_texture_pixel()
    std::vector<Vec3> vertices;
    std::vector<uint8_t> visibility;
    std::vector<Node> nodes;
    std::vector<Texinfo> texinfo;
    std::vector<Face> faces;
    std::vector<uint8_t> lighting;
    std::vector<ClipNode> clipnodes;
    std::vector<Leaf> leafs;
    std::vector<int64_t> marksurfaces;
    std::vector<std::array<int64_t, 2>> edges;
    std::vector<int32_t> surfedges;
    std::vector<Model> models;
};

// Palette index of pixel (x, y) of mip `level` of texture `texture` as write_bsp stores it.
uint8_t synth_texture_pixel(size_t texture, int level, uint32_t x, uint32_t y);

// Layout: 124-byte header, then the 15 lumps in directory order, each starting 4-byte aligned.
std::vector<uint8_t> write_bsp(const SynthBsp& bsp, BspFormat format);
// Byte position of lump `lump`'s (offset, length) pair in the header.
inline size_t synth_bsp_directory_entry(int lump) {
    return 4 + 8 * static_cast<size_t>(lump);
}

// Facts of make_box_room(), for tests to compare with.
namespace box_room {
inline constexpr std::array<float, 3> kRoomMins{-128, -128, -64};  // inside of the walls
inline constexpr std::array<float, 3> kRoomMaxs{128, 128, 128};
inline constexpr std::array<float, 3> kCrateMins{64, 64, -64};  // model 1, a solid box
inline constexpr std::array<float, 3> kCrateMaxs{96, 96, -32};
inline constexpr std::array<float, 3> kPlayerStart{0, 0, -32};
inline constexpr int kFacesPerBox = 6;
inline constexpr uint32_t kRoomLeaf = 1;   // leaf 0 is the solid leaf
inline constexpr uint32_t kCrateLeaf = 2;  // the empty leaf around the crate in model 1
}  // namespace box_room

// A closed room (model 0: six inward faces, one empty leaf, PVS where the leaf sees itself)
// holding a crate (model 1: six outward faces), textures "wall" 16x16 and "floor" 32x16, a
// lightmap for every face (the ceiling with two styles), hulls 1 and 2, and entities
// worldspawn, info_player_start, light and func_wall "*1". Valid in every format.
SynthBsp make_box_room();

// Box rooms in BSP29, BSP2 and 2PSB, plus variants (missing texture, no PVS).
std::vector<SeedFile> synthetic_bsp_seeds();

}  // namespace nq::test
