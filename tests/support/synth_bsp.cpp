#include "support/synth_bsp.h"

#include <cmath>
#include <cstring>
#include <map>
#include <utility>

namespace nq::test {

namespace {

using Vec3 = SynthBsp::Vec3;

// ---- Little-endian output ----

class Out {
  public:
    void u8(uint8_t v) { bytes_.push_back(v); }
    void u16(uint64_t v) {
        u8(static_cast<uint8_t>(v));
        u8(static_cast<uint8_t>(v >> 8));
    }
    void u32(uint64_t v) {
        u16(v & 0xffff);
        u16((v >> 16) & 0xffff);
    }
    void f32(float f) {
        uint32_t bits;
        std::memcpy(&bits, &f, 4);
        u32(bits);
    }
    void vec3(const Vec3& v) {
        for (float c : v) f32(c);
    }
    // 16 bits in BSP29, 32 in the wide formats.
    void index(uint64_t v, bool wide) { wide ? u32(v) : u16(v); }
    void name16(const std::string& s) {
        for (size_t i = 0; i < 16; ++i) u8(i < s.size() ? static_cast<uint8_t>(s[i]) : 0);
    }
    void append(const std::vector<uint8_t>& b) { bytes_.insert(bytes_.end(), b.begin(), b.end()); }
    void align4() {
        while (bytes_.size() % 4 != 0) u8(0);
    }
    void put_u32_at(size_t at, uint32_t v) {
        for (int i = 0; i < 4; ++i) bytes_[at + i] = static_cast<uint8_t>(v >> (8 * i));
    }
    size_t size() const { return bytes_.size(); }
    std::vector<uint8_t>& bytes() { return bytes_; }

  private:
    std::vector<uint8_t> bytes_;
};

// ---- Lump writers ----

void write_bounds(Out& o, const Vec3& mins, const Vec3& maxs, BspFormat format) {
    if (format == BspFormat::bsp2) {
        o.vec3(mins);
        o.vec3(maxs);
        return;
    }
    for (float c : mins) o.u16(static_cast<uint16_t>(static_cast<int16_t>(c)));
    for (float c : maxs) o.u16(static_cast<uint16_t>(static_cast<int16_t>(c)));
}

std::vector<uint8_t> texture_lump(const SynthBsp& bsp) {
    Out o;
    o.u32(bsp.textures.size());
    const size_t table = o.size();
    for (size_t i = 0; i < bsp.textures.size(); ++i) o.u32(0);
    for (size_t i = 0; i < bsp.textures.size(); ++i) {
        const SynthBsp::Texture& t = bsp.textures[i];
        if (t.missing) {
            o.put_u32_at(table + 4 * i, 0xffffffffu);
            continue;
        }
        const size_t start = o.size();
        o.put_u32_at(table + 4 * i, static_cast<uint32_t>(start));
        o.name16(t.name);
        o.u32(t.width);
        o.u32(t.height);
        uint32_t offset = 40;
        for (int level = 0; level < 4; ++level) {
            o.u32(offset);
            offset += (t.width >> level) * (t.height >> level);
        }
        for (int level = 0; level < 4; ++level) {
            for (uint32_t y = 0; y < (t.height >> level); ++y) {
                for (uint32_t x = 0; x < (t.width >> level); ++x) {
                    o.u8(synth_texture_pixel(i, level, x, y));
                }
            }
        }
    }
    return std::move(o.bytes());
}

std::vector<uint8_t> lump_bytes(const SynthBsp& bsp, int lump, BspFormat format) {
    const bool wide = format != BspFormat::bsp29;
    Out o;
    switch (lump) {
        case 0:
            for (char c : bsp.entities) o.u8(static_cast<uint8_t>(c));
            o.u8(0);
            break;
        case 1:
            for (const auto& p : bsp.planes) {
                o.vec3(p.normal);
                o.f32(p.dist);
                o.u32(static_cast<uint32_t>(p.type));
            }
            break;
        case 2:
            return texture_lump(bsp);
        case 3:
            for (const auto& v : bsp.vertices) o.vec3(v);
            break;
        case 4:
            return bsp.visibility;
        case 5:
            for (const auto& n : bsp.nodes) {
                o.u32(static_cast<uint64_t>(n.plane));
                for (int64_t c : n.children) o.index(static_cast<uint64_t>(c), wide);
                write_bounds(o, n.mins, n.maxs, format);
                o.index(static_cast<uint64_t>(n.first_face), wide);
                o.index(static_cast<uint64_t>(n.num_faces), wide);
            }
            break;
        case 6:
            for (const auto& t : bsp.texinfo) {
                for (const auto& axis : t.vecs) {
                    for (float c : axis) o.f32(c);
                }
                o.u32(static_cast<uint32_t>(t.miptex));
                o.u32(t.flags);
            }
            break;
        case 7:
            for (const auto& f : bsp.faces) {
                o.index(static_cast<uint64_t>(f.plane), wide);
                o.index(static_cast<uint64_t>(f.side), wide);
                o.u32(static_cast<uint64_t>(f.first_surfedge));
                o.index(static_cast<uint64_t>(f.num_surfedges), wide);
                o.index(static_cast<uint64_t>(f.texinfo), wide);
                for (uint8_t s : f.styles) o.u8(s);
                o.u32(static_cast<uint32_t>(f.light_offset));
            }
            break;
        case 8:
            return bsp.lighting;
        case 9:
            for (const auto& c : bsp.clipnodes) {
                o.u32(static_cast<uint64_t>(c.plane));
                for (int64_t child : c.children) o.index(static_cast<uint64_t>(child), wide);
            }
            break;
        case 10:
            for (const auto& l : bsp.leafs) {
                o.u32(static_cast<uint32_t>(l.contents));
                o.u32(static_cast<uint32_t>(l.vis_offset));
                write_bounds(o, l.mins, l.maxs, format);
                o.index(static_cast<uint64_t>(l.first_marksurface), wide);
                o.index(static_cast<uint64_t>(l.num_marksurfaces), wide);
                for (uint8_t a : l.ambient) o.u8(a);
            }
            break;
        case 11:
            for (int64_t m : bsp.marksurfaces) o.index(static_cast<uint64_t>(m), wide);
            break;
        case 12:
            for (const auto& e : bsp.edges) {
                for (int64_t v : e) o.index(static_cast<uint64_t>(v), wide);
            }
            break;
        case 13:
            for (int32_t s : bsp.surfedges) o.u32(static_cast<uint32_t>(s));
            break;
        case 14:
            for (const auto& m : bsp.models) {
                o.vec3(m.mins);
                o.vec3(m.maxs);
                o.vec3(m.origin);
                for (int32_t h : m.headnodes) o.u32(static_cast<uint32_t>(h));
                o.u32(static_cast<uint32_t>(m.visleafs));
                o.u32(static_cast<uint32_t>(m.first_face));
                o.u32(static_cast<uint32_t>(m.num_faces));
            }
            break;
    }
    return std::move(o.bytes());
}

uint32_t magic(BspFormat format) {
    switch (format) {
        case BspFormat::bsp29:
            return 29;
        case BspFormat::bsp2:
            return 0x32505342;  // "BSP2"
        case BspFormat::bsp2psb:
            return 0x42535032;  // "2PSB"
    }
    return 0;
}

// ---- Box room construction ----

Vec3 corner(const Vec3& mins, const Vec3& maxs, int bits) {
    return {bits & 1 ? maxs[0] : mins[0], bits & 2 ? maxs[1] : mins[1],
            bits & 4 ? maxs[2] : mins[2]};
}

Vec3 sub(const Vec3& a, const Vec3& b) {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
float dot(const Vec3& a, const Vec3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

class BoxBuilder {
  public:
    explicit BoxBuilder(SynthBsp& bsp) : bsp_(bsp) {
        bsp_.edges.push_back({0, 0});  // edge 0 is never used: -0 could not mean "reversed"
    }

    // Adds one model: a room (empty inside, faces looking in) or a solid box (faces looking
    // out), with its node chain, its one empty leaf, clip hulls 1 and 2, and lightmaps.
    void add_box(const Vec3& mins, const Vec3& maxs, bool room, int32_t leaf_vis_offset) {
        SynthBsp::Model model;
        model.mins = mins;
        model.maxs = maxs;
        model.first_face = static_cast<int32_t>(bsp_.faces.size());
        model.num_faces = 6;
        model.visleafs = 1;
        const int64_t leaf = static_cast<int64_t>(bsp_.leafs.size());
        const int64_t first_mark = static_cast<int64_t>(bsp_.marksurfaces.size());
        const int64_t first_node = static_cast<int64_t>(bsp_.nodes.size());
        model.headnodes[0] = static_cast<int32_t>(first_node);
        for (int side = 0; side < 6; ++side) {
            const int axis = side / 2;
            const bool max_side = side % 2 != 0;
            const int64_t plane = add_plane(axis, max_side ? maxs[axis] : mins[axis]);
            // Facing direction: rooms look inwards, crates outwards.
            const bool faces_negative = room == max_side;
            const int64_t face = add_face(mins, maxs, axis, max_side, plane, faces_negative, room);
            bsp_.marksurfaces.push_back(face);
            add_node_link(plane, room, max_side, side == 5, -(leaf + 1), face, mins, maxs);
        }
        SynthBsp::Leaf l;
        l.contents = -1;
        l.vis_offset = leaf_vis_offset;
        l.mins = mins;
        l.maxs = maxs;
        l.first_marksurface = first_mark;
        l.num_marksurfaces = 6;
        bsp_.leafs.push_back(l);
        model.headnodes[1] = add_clip_chain(mins, maxs, room, {-16, -16, -24}, {16, 16, 32});
        model.headnodes[2] = add_clip_chain(mins, maxs, room, {-32, -32, -24}, {32, 32, 64});
        bsp_.models.push_back(model);
    }

  private:
    int64_t add_plane(int axis, float dist) {
        SynthBsp::Plane p;
        p.normal[axis] = 1;
        p.dist = dist;
        p.type = axis;
        bsp_.planes.push_back(p);
        return static_cast<int64_t>(bsp_.planes.size() - 1);
    }

    // A node of the chain for one side. Inside the box is the front of a min-side plane and
    // the back of a max-side plane; the inside leads on to the next side's node.
    void add_node_link(int64_t plane, bool room, bool max_side, bool last, int64_t own_leaf,
                       int64_t face, const Vec3& mins, const Vec3& maxs) {
        const int64_t next =
            last ? (room ? own_leaf : -1) : static_cast<int64_t>(bsp_.nodes.size() + 1);
        const int64_t outside = room ? -1 : own_leaf;  // -1: leaf 0, the solid leaf
        SynthBsp::Node n;
        n.plane = plane;
        n.children = max_side ? std::array<int64_t, 2>{outside, next}
                              : std::array<int64_t, 2>{next, outside};
        n.mins = mins;
        n.maxs = maxs;
        n.first_face = face;
        n.num_faces = 1;
        bsp_.nodes.push_back(n);
    }

    // The same chain for a hull whose box spans cmins..cmaxs: planes move by the box so that
    // a point in the hull is where the box's origin may (not) go.
    int32_t add_clip_chain(const Vec3& mins, const Vec3& maxs, bool room, const Vec3& cmins,
                           const Vec3& cmaxs) {
        const auto head = static_cast<int32_t>(bsp_.clipnodes.size());
        for (int side = 0; side < 6; ++side) {
            const int axis = side / 2;
            const bool max_side = side % 2 != 0;
            // Room: free space is [mins - cmins, maxs - cmaxs]; crate: solid space is
            // [mins - cmaxs, maxs - cmins].
            const float dist =
                room ? (max_side ? maxs[axis] - cmaxs[axis] : mins[axis] - cmins[axis])
                     : (max_side ? maxs[axis] - cmins[axis] : mins[axis] - cmaxs[axis]);
            const int64_t plane = add_plane(axis, dist);
            const int64_t next =
                side == 5 ? (room ? -1 : -2) : static_cast<int64_t>(bsp_.clipnodes.size() + 1);
            const int64_t outside = room ? -2 : -1;
            SynthBsp::ClipNode c;
            c.plane = plane;
            c.children = max_side ? std::array<int64_t, 2>{outside, next}
                                  : std::array<int64_t, 2>{next, outside};
            bsp_.clipnodes.push_back(c);
        }
        return head;
    }

    int64_t add_face(const Vec3& mins, const Vec3& maxs, int axis, bool max_side, int64_t plane,
                     bool faces_negative, bool room) {
        // The four corners on this side, in a ring.
        const int fixed_bit = 1 << axis;
        const int a = 1 << ((axis + 1) % 3);
        const int b = 1 << ((axis + 2) % 3);
        const int base = max_side ? fixed_bit : 0;
        std::array<int, 4> ring{base, base | a, base | a | b, base | b};
        Vec3 facing{};
        facing[axis] = faces_negative ? -1.f : 1.f;
        std::array<Vec3, 4> p;
        for (int i = 0; i < 4; ++i) p[i] = corner(mins, maxs, ring[i]);
        // Quake winds faces clockwise seen from the front: (p0 - p1) x (p2 - p1) faces out.
        if (dot(cross(sub(p[0], p[1]), sub(p[2], p[1])), facing) < 0) std::swap(p[1], p[3]);

        SynthBsp::Face f;
        f.plane = plane;
        f.side = faces_negative ? 1 : 0;
        f.first_surfedge = static_cast<int64_t>(bsp_.surfedges.size());
        f.num_surfedges = 4;
        f.texinfo = axis;  // texinfo 0: x walls, 1: y walls, 2: floor and ceiling
        for (int i = 0; i < 4; ++i) bsp_.surfedges.push_back(edge(p[i], p[(i + 1) % 4]));
        const bool ceiling = room && axis == 2 && max_side;  // the room's: two light styles
        if (ceiling) f.styles = {0, 1, 255, 255};
        f.light_offset = static_cast<int32_t>(bsp_.lighting.size());
        append_lightmap(p, bsp_.texinfo[static_cast<size_t>(axis)], ceiling ? 2 : 1);
        bsp_.faces.push_back(f);
        return static_cast<int64_t>(bsp_.faces.size() - 1);
    }

    uint32_t vertex(const Vec3& v) {
        for (size_t i = 0; i < bsp_.vertices.size(); ++i) {
            if (bsp_.vertices[i] == v) return static_cast<uint32_t>(i);
        }
        bsp_.vertices.push_back(v);
        return static_cast<uint32_t>(bsp_.vertices.size() - 1);
    }

    // A surfedge for a -> b, sharing the edge of a neighbour walked the other way (negative).
    int32_t edge(const Vec3& a, const Vec3& b) {
        const uint32_t va = vertex(a), vb = vertex(b);
        if (auto it = edges_.find({vb, va}); it != edges_.end()) return -it->second;
        bsp_.edges.push_back({va, vb});
        const auto index = static_cast<int32_t>(bsp_.edges.size() - 1);
        edges_[{va, vb}] = index;
        return index;
    }

    // Lightmap size from the face's texel bounds snapped to 16; samples get a ramp.
    void append_lightmap(const std::array<Vec3, 4>& p, const SynthBsp::Texinfo& tex, int styles) {
        uint32_t size[2];
        for (int axis = 0; axis < 2; ++axis) {
            float lo = 1e30f, hi = -1e30f;
            for (const Vec3& v : p) {
                const float s = v[0] * tex.vecs[axis][0] + v[1] * tex.vecs[axis][1] +
                                v[2] * tex.vecs[axis][2] + tex.vecs[axis][3];
                lo = std::min(lo, s);
                hi = std::max(hi, s);
            }
            size[axis] = static_cast<uint32_t>(std::ceil(hi / 16) - std::floor(lo / 16)) + 1;
        }
        const size_t samples = size_t{size[0]} * size[1] * static_cast<size_t>(styles);
        for (size_t i = 0; i < samples; ++i) {
            bsp_.lighting.push_back(static_cast<uint8_t>(64 + (bsp_.lighting.size() % 128)));
        }
    }

    SynthBsp& bsp_;
    std::map<std::pair<uint32_t, uint32_t>, int32_t> edges_;
};

SynthBsp::Texinfo texinfo_for(int axis) {
    // Quake's usual projection: each axis-facing face takes the other two axes as s and t.
    SynthBsp::Texinfo t;
    if (axis == 0) t.vecs = {{{0, 1, 0, 0}, {0, 0, -1, 0}}};
    if (axis == 1) t.vecs = {{{1, 0, 0, 0}, {0, 0, -1, 0}}};
    if (axis == 2) t.vecs = {{{1, 0, 0, 0}, {0, -1, 0, 0}}};
    t.miptex = axis == 2 ? 1 : 0;
    return t;
}

const char kBoxEntities[] =
    "{\n\"classname\" \"worldspawn\"\n\"wad\" \"gfx.wad\"\n\"message\" \"Synthetic box room\"\n"
    "\"sky\" \"sky1\"\n}\n"
    "{\n\"classname\" \"info_player_start\"\n\"origin\" \"0 0 -32\"\n\"angle\" \"90\"\n}\n"
    "{\n\"classname\" \"light\"\n\"origin\" \"0 0 96\"\n\"light\" \"300\"\n"
    "\"_color\" \"1 0.5 0.25\"\n}\n"
    "{\n\"classname\" \"func_wall\"\n\"model\" \"*1\"\n}\n";

}  // namespace

uint8_t synth_texture_pixel(size_t texture, int level, uint32_t x, uint32_t y) {
    return static_cast<uint8_t>(texture * 50 + static_cast<size_t>(level) * 17 + x + y * 3);
}

std::vector<uint8_t> write_bsp(const SynthBsp& bsp, BspFormat format) {
    Out o;
    o.u32(magic(format));
    for (int i = 0; i < 15; ++i) o.u32(0), o.u32(0);
    for (int lump = 0; lump < 15; ++lump) {
        o.align4();
        const size_t at = o.size();
        auto bytes = lump_bytes(bsp, lump, format);
        o.append(bytes);
        o.put_u32_at(synth_bsp_directory_entry(lump), static_cast<uint32_t>(at));
        o.put_u32_at(synth_bsp_directory_entry(lump) + 4, static_cast<uint32_t>(bytes.size()));
    }
    return std::move(o.bytes());
}

SynthBsp make_box_room() {
    SynthBsp bsp;
    bsp.entities = kBoxEntities;
    bsp.textures = {{"wall", 16, 16, false}, {"floor", 32, 16, false}};
    for (int axis = 0; axis < 3; ++axis) bsp.texinfo.push_back(texinfo_for(axis));
    SynthBsp::Leaf solid;
    solid.contents = -2;
    bsp.leafs.push_back(solid);
    BoxBuilder builder(bsp);
    builder.add_box(box_room::kRoomMins, box_room::kRoomMaxs, true, 0);
    builder.add_box(box_room::kCrateMins, box_room::kCrateMaxs, false, -1);
    bsp.visibility = {0x01};  // one world leaf, which sees itself
    return bsp;
}

std::vector<SeedFile> synthetic_bsp_seeds() {
    const SynthBsp room = make_box_room();
    std::vector<SeedFile> seeds = {
        {"box_bsp29.bsp", write_bsp(room, BspFormat::bsp29)},
        {"box_bsp2.bsp", write_bsp(room, BspFormat::bsp2)},
        {"box_2psb.bsp", write_bsp(room, BspFormat::bsp2psb)},
    };
    SynthBsp missing = room;
    missing.textures[1].missing = true;
    seeds.push_back({"box_missing_texture_bsp29.bsp", write_bsp(missing, BspFormat::bsp29)});
    SynthBsp novis = room;
    novis.visibility.clear();
    novis.leafs[box_room::kRoomLeaf].vis_offset = -1;
    seeds.push_back({"box_novis_bsp2.bsp", write_bsp(novis, BspFormat::bsp2)});
    return seeds;
}

}  // namespace nq::test
