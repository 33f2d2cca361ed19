// Readers for the record lumps. Each reads one lump in the file's format (BSP29 16-bit fields or
// BSP2/2PSB 32-bit ones) and checks every index it meets against the directory's record counts.
#include <climits>

#include "formats/bsp_internal.h"

namespace nq::bsp_detail {

namespace {

std::string item(const char* kind, size_t index) {
    return kind + (" " + std::to_string(index));
}

BspVec3 read_vec3(ByteReader& r) {
    BspVec3 v;
    for (float& c : v) c = r.f32_finite();
    return v;
}

// Node and leaf bounds: floats in BSP2, shorts in BSP29 and 2PSB.
void read_bounds(ByteReader& r, BspFormat format, BspVec3& mins, BspVec3& maxs) {
    if (format == BspFormat::bsp2) {
        mins = read_vec3(r);
        maxs = read_vec3(r);
        return;
    }
    for (float& c : mins) c = r.i16();
    for (float& c : maxs) c = r.i16();
}

// Index and count fields are 16 bits in BSP29, read unsigned as modern engines do so that maps
// with more than 32767 records keep working, and 32 bits in BSP2/2PSB, where the format declares
// some of them signed (faces, models) and some unsigned (leafs, nodes, edges, marksurfaces).
int64_t read_u16_or_i32(ByteReader& r, bool wide) {
    return wide ? int64_t{r.i32()} : int64_t{r.u16()};
}
int64_t read_u16_or_u32(ByteReader& r, bool wide) {
    return wide ? int64_t{r.u32()} : int64_t{r.u16()};
}

// A contents value stored as a clip-tree child must be one Quake defines.
bool is_contents(int64_t value) {
    return value < 0 && value >= bsp_contents::lowest_valid;
}

// BSP29 node children are 16-bit. Values below the node count are nodes; the rest count down
// from 65535 as leafs (65535 = leaf 0), which is the usual reading of -(leaf + 1) as a signed
// short, extended to maps with more than 32767 nodes or leafs.
int32_t node_child(ByteReader& r, const ReadContext& ctx, size_t node, int side) {
    const size_t at = r.tell();
    const size_t nodes = ctx.count(kNodes);
    const size_t leafs = ctx.count(kLeafs);
    int64_t child = read_u16_or_i32(r, ctx.wide());
    if (!ctx.wide() && child >= static_cast<int64_t>(nodes)) child -= 65536;
    if (child >= 0) {
        check_index(r, at, child, nodes,
                    {"node", node, side ? "back child node" : "front child node"});
    } else {
        check_index(r, at, -(child + 1), leafs,
                    {"node", node, side ? "back child leaf" : "front child leaf"});
    }
    return static_cast<int32_t>(child);
}

// Clipnode children: a clipnode index or a contents value; BSP29 reads them unsigned like node
// children, so 65535 is -1 (empty) and 65534 is -2 (solid).
int32_t clip_child(ByteReader& r, const ReadContext& ctx, size_t clipnode, int side) {
    const size_t at = r.tell();
    const size_t clipnodes = ctx.count(kClipnodes);
    int64_t child = read_u16_or_i32(r, ctx.wide());
    if (!ctx.wide() && child >= static_cast<int64_t>(clipnodes)) child -= 65536;
    const FieldName what{"clipnode", clipnode, side ? "back child" : "front child"};
    if (child >= 0) {
        check_index(r, at, child, clipnodes, what);
    } else if (!is_contents(child)) {
        r.fail_at(at, what.str() + " " + std::to_string(child) + " is neither a clipnode (" +
                          std::to_string(clipnodes) + " available) nor a contents value (-1..-15)");
    }
    return static_cast<int32_t>(child);
}

}  // namespace

void read_entities(const ReadContext& ctx) {
    auto r = ctx.lump_reader(kEntities);
    auto bytes = r.bytes(r.size());
    size_t end = 0;
    while (end < bytes.size() && bytes[end] != 0) ++end;
    if (end == bytes.size() && !bytes.empty()) {
        ctx.out.warnings.push_back("entity lump is not NUL-terminated");
    }
    ctx.out.entities.assign(reinterpret_cast<const char*>(bytes.data()), end);
    ctx.out.entities_offset = r.absolute(0);
}

void read_planes(const ReadContext& ctx) {
    auto r = ctx.lump_reader(kPlanes);
    auto& planes = ctx.out.planes;
    planes.resize(ctx.count(kPlanes));
    for (BspPlane& p : planes) {
        p.normal = read_vec3(r);
        p.dist = r.f32_finite();
        p.type = r.i32();
    }
}

void read_vertices(const ReadContext& ctx) {
    auto r = ctx.lump_reader(kVertexes);
    auto& vertices = ctx.out.vertices;
    vertices.resize(ctx.count(kVertexes));
    for (BspVec3& v : vertices) v = read_vec3(r);
}

void read_texinfo(const ReadContext& ctx) {
    auto r = ctx.lump_reader(kTexinfo);
    const size_t textures = ctx.out.textures.size();
    auto& texinfo = ctx.out.texinfo;
    texinfo.resize(ctx.count(kTexinfo));
    for (size_t i = 0; i < texinfo.size(); ++i) {
        for (auto& axis : texinfo[i].vecs) {
            for (float& c : axis) c = r.f32_finite();
        }
        const size_t at = r.tell();
        const int32_t miptex = r.i32();
        check_index(r, at, miptex, textures, {"texinfo", i, "miptex"});
        texinfo[i].miptex = static_cast<uint32_t>(miptex);
        texinfo[i].flags = r.u32();
    }
}

void read_faces(const ReadContext& ctx) {
    auto r = ctx.lump_reader(kFaces);
    const bool wide = ctx.wide();
    auto& faces = ctx.out.faces;
    faces.resize(ctx.count(kFaces));
    for (size_t i = 0; i < faces.size(); ++i) {
        BspFace& f = faces[i];
        size_t at = r.tell();
        const int64_t plane = read_u16_or_i32(r, wide);
        check_index(r, at, plane, ctx.count(kPlanes), {"face", i, "plane"});
        f.plane = static_cast<uint32_t>(plane);
        f.back_side = (wide ? r.i32() : r.i16()) != 0;
        at = r.tell();
        const int64_t first = r.i32();
        const int64_t num = read_u16_or_i32(r, wide);
        if (num < 3) {
            r.fail_at(at + 4,
                      item("face", i) + " has " + std::to_string(num) + " edges (3 needed)");
        }
        check_range(r, at, first, num, ctx.count(kSurfedges), {"face", i, "surfedges"});
        f.first_surfedge = static_cast<uint32_t>(first);
        f.num_surfedges = static_cast<uint32_t>(num);
        at = r.tell();
        const int64_t texinfo = read_u16_or_i32(r, wide);
        check_index(r, at, texinfo, ctx.count(kTexinfo), {"face", i, "texinfo"});
        f.texinfo = static_cast<uint32_t>(texinfo);
        for (uint8_t& s : f.styles) s = r.u8();
        at = r.tell();
        f.light_offset = r.i32();
        if (f.light_offset < -1) {
            r.fail_at(at, item("face", i) + " has negative light offset " +
                              std::to_string(f.light_offset));
        }
    }
}

void read_edges(const ReadContext& ctx) {
    auto r = ctx.lump_reader(kEdges);
    const size_t vertices = ctx.count(kVertexes);
    auto& edges = ctx.out.edges;
    edges.resize(ctx.count(kEdges));
    for (size_t i = 0; i < edges.size(); ++i) {
        for (uint32_t& v : edges[i].v) {
            const size_t at = r.tell();
            const int64_t index = read_u16_or_u32(r, ctx.wide());
            check_index(r, at, index, vertices, {"edge", i, "vertex"});
            v = static_cast<uint32_t>(index);
        }
    }
}

void read_surfedges(const ReadContext& ctx) {
    auto r = ctx.lump_reader(kSurfedges);
    const size_t edges = ctx.count(kEdges);
    auto& surfedges = ctx.out.surfedges;
    surfedges.resize(ctx.count(kSurfedges));
    for (size_t i = 0; i < surfedges.size(); ++i) {
        const size_t at = r.tell();
        const int32_t e = r.i32();
        // INT_MIN has no positive counterpart: it cannot name a reversed edge.
        if (e == INT32_MIN) r.fail_at(at, item("surfedge", i) + " is INT_MIN (no such edge)");
        check_index(r, at, e < 0 ? -int64_t{e} : int64_t{e}, edges, {"surfedge", i, "edge"});
        surfedges[i] = e;
    }
}

void read_marksurfaces(const ReadContext& ctx) {
    auto r = ctx.lump_reader(kMarksurfaces);
    const size_t faces = ctx.count(kFaces);
    auto& marks = ctx.out.marksurfaces;
    marks.resize(ctx.count(kMarksurfaces));
    for (size_t i = 0; i < marks.size(); ++i) {
        const size_t at = r.tell();
        const int64_t face = read_u16_or_u32(r, ctx.wide());
        check_index(r, at, face, faces, {"marksurface", i, "face"});
        marks[i] = static_cast<uint32_t>(face);
    }
}

void read_leafs(const ReadContext& ctx) {
    auto r = ctx.lump_reader(kLeafs);
    const size_t vis_bytes = ctx.lumps[kVisibility].length;
    auto& leafs = ctx.out.leafs;
    leafs.resize(ctx.count(kLeafs));
    for (size_t i = 0; i < leafs.size(); ++i) {
        BspLeaf& leaf = leafs[i];
        size_t at = r.tell();
        leaf.contents = r.i32();
        if (!is_contents(leaf.contents)) {
            r.fail_at(at, item("leaf", i) + " has contents " + std::to_string(leaf.contents) +
                              " (expected -1..-15)");
        }
        at = r.tell();
        leaf.vis_offset = r.i32();
        if (i == 0) {
            leaf.vis_offset = -1;  // the solid leaf sees nothing; compilers leave 0 or -1 here
        } else if (leaf.vis_offset < -1 ||
                   (leaf.vis_offset >= 0 && static_cast<size_t>(leaf.vis_offset) > vis_bytes)) {
            r.fail_at(at, item("leaf", i) + " visibility offset " +
                              std::to_string(leaf.vis_offset) +
                              " lies outside the visibility lump (" + std::to_string(vis_bytes) +
                              " bytes)");
        }
        read_bounds(r, ctx.format, leaf.mins, leaf.maxs);
        at = r.tell();
        const int64_t first = read_u16_or_u32(r, ctx.wide());
        const int64_t num = read_u16_or_u32(r, ctx.wide());
        check_range(r, at, first, num, ctx.count(kMarksurfaces), {"leaf", i, "marksurfaces"});
        leaf.first_marksurface = static_cast<uint32_t>(first);
        leaf.num_marksurfaces = static_cast<uint32_t>(num);
        for (uint8_t& a : leaf.ambient_levels) a = r.u8();
    }
}

void read_nodes(const ReadContext& ctx) {
    auto r = ctx.lump_reader(kNodes);
    auto& nodes = ctx.out.nodes;
    nodes.resize(ctx.count(kNodes));
    for (size_t i = 0; i < nodes.size(); ++i) {
        BspNode& node = nodes[i];
        size_t at = r.tell();
        const int32_t plane = r.i32();
        check_index(r, at, plane, ctx.count(kPlanes), {"node", i, "plane"});
        node.plane = static_cast<uint32_t>(plane);
        node.children[0] = node_child(r, ctx, i, 0);
        node.children[1] = node_child(r, ctx, i, 1);
        read_bounds(r, ctx.format, node.mins, node.maxs);
        at = r.tell();
        const int64_t first = read_u16_or_u32(r, ctx.wide());
        const int64_t num = read_u16_or_u32(r, ctx.wide());
        check_range(r, at, first, num, ctx.count(kFaces), {"node", i, "faces"});
        node.first_face = static_cast<uint32_t>(first);
        node.num_faces = static_cast<uint32_t>(num);
    }
}

void read_clipnodes(const ReadContext& ctx) {
    auto r = ctx.lump_reader(kClipnodes);
    auto& clipnodes = ctx.out.hulls[1].clipnodes;
    clipnodes.resize(ctx.count(kClipnodes));
    for (size_t i = 0; i < clipnodes.size(); ++i) {
        const size_t at = r.tell();
        const int32_t plane = r.i32();
        check_index(r, at, plane, ctx.count(kPlanes), {"clipnode", i, "plane"});
        clipnodes[i].plane = static_cast<uint32_t>(plane);
        clipnodes[i].children[0] = clip_child(r, ctx, i, 0);
        clipnodes[i].children[1] = clip_child(r, ctx, i, 1);
    }
}

void read_models(const ReadContext& ctx) {
    auto r = ctx.lump_reader(kModels);
    auto& models = ctx.out.models;
    if (ctx.count(kModels) == 0) r.fail_at(0, "no models: the world model (model 0) is missing");
    models.resize(ctx.count(kModels));
    for (size_t i = 0; i < models.size(); ++i) {
        BspModel& m = models[i];
        m.mins = read_vec3(r);
        m.maxs = read_vec3(r);
        m.origin = read_vec3(r);
        size_t at = r.tell();
        for (int32_t& h : m.headnodes) h = r.i32();
        check_index(r, at, m.headnodes[0], ctx.count(kNodes), {"model", i, "hull 0 head node"});
        for (int hull = 1; hull <= 2; ++hull) {
            const int32_t head = m.headnodes[hull];
            if (head < 0 && is_contents(head)) continue;  // the whole hull is one contents
            check_index(r, at + 4 * hull, head, ctx.count(kClipnodes),
                        {"model", i, hull == 1 ? "hull 1 head clipnode" : "hull 2 head clipnode"});
        }
        at = r.tell();
        const int32_t visleafs = r.i32();
        // Leaf 0 is shared and never counted, so a model has at most numleafs - 1 leafs.
        const size_t leafs = ctx.count(kLeafs);
        if (visleafs < 0 || static_cast<size_t>(visleafs) >= leafs) {
            r.fail_at(at, item("model", i) + " visleafs " + std::to_string(visleafs) +
                              " out of range (" + std::to_string(leafs) +
                              " leafs including leaf 0)");
        }
        m.visleafs = static_cast<uint32_t>(visleafs);
        at = r.tell();
        const int32_t first = r.i32();
        const int32_t num = r.i32();
        check_range(r, at, first, num, ctx.count(kFaces), {"model", i, "faces"});
        m.first_face = static_cast<uint32_t>(first);
        m.num_faces = static_cast<uint32_t>(num);
    }
}

}  // namespace nq::bsp_detail
