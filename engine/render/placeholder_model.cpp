#include "render/placeholder_model.h"

#include <array>

namespace nq {

namespace {

constexpr int kSkinSize = 8;
constexpr uint8_t kUpNormalIndex = 5;

// Corner i has x = bit 0, y = bit 1, z = bit 2 (0 = min, 1 = max).
TriVertex corner_vertex(int i) {
    TriVertex v;
    for (int axis = 0; axis < 3; ++axis) v.v[axis] = (i >> axis) & 1 ? 255 : 0;
    v.light_normal_index = kUpNormalIndex;
    return v;
}

// Two triangles per side, clockwise seen from outside like Quake's alias triangles (and world
// faces); all skin coordinates are 0 since the skin is one colour.
constexpr std::array<std::array<int32_t, 3>, 12> kBoxTriangles = {{
    {0, 3, 2},
    {0, 1, 3},  // z min
    {4, 7, 5},
    {4, 6, 7},  // z max
    {0, 5, 1},
    {0, 4, 5},  // y min
    {2, 7, 6},
    {2, 3, 7},  // y max
    {0, 6, 4},
    {0, 2, 6},  // x min
    {1, 7, 3},
    {1, 5, 7},  // x max
}};

Mdl placeholder_mdl() {
    Mdl mdl;
    MdlHeader& h = mdl.header;
    h.version = kMdlVersion;
    const float size = 2 * kPlaceholderHalfSize;
    h.scale = {size / 255, size / 255, size / 255};
    h.scale_origin = {-kPlaceholderHalfSize, -kPlaceholderHalfSize, -kPlaceholderHalfSize};
    h.bounding_radius = kPlaceholderHalfSize * 1.7320508f;
    h.num_skins = 1;
    h.skin_width = h.skin_height = kSkinSize;
    h.num_verts = 8;
    h.num_tris = static_cast<int32_t>(kBoxTriangles.size());
    h.num_frames = 1;

    MdlSkin skin;
    skin.images.emplace_back(size_t{kSkinSize} * kSkinSize, kPlaceholderColor);
    mdl.skins.push_back(std::move(skin));
    mdl.tex_coords.resize(8);
    for (const auto& t : kBoxTriangles) mdl.triangles.push_back({1, t});

    MdlPose pose;
    pose.name = "placeholder";
    pose.bbox_min = corner_vertex(0);
    pose.bbox_max = corner_vertex(7);
    for (int i = 0; i < 8; ++i) pose.vertices.push_back(corner_vertex(i));
    MdlFrame frame;
    frame.poses.push_back(std::move(pose));
    mdl.frames.push_back(std::move(frame));
    return mdl;
}

}  // namespace

std::shared_ptr<const AliasModelData> make_placeholder_alias() {
    return AliasModelData::build(placeholder_mdl());
}

}  // namespace nq
