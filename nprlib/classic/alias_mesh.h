// CPU side of an alias model (MDL): the triangle mesh with skin coordinates, and every pose's
// vertices packed for a GPU buffer texture so the vertex shader can blend any two poses.
//
// Skin coordinates follow Quake: a vertex on the seam used by a back-facing triangle
// (facesfront = 0) takes s + skin_width / 2, so such vertices are duplicated; texture coordinates
// are (s + 0.5) / skin_width, (t + 0.5) / skin_height.
//
// Normals: MDL vertices carry an index into id's table of 162 precomputed normals. nprlib does
// not embed that table (it is id's code, not a fact we can restate); instead each pose's smooth
// vertex normals are computed from its triangles (angle-weighted), which matches the table's
// directions to within its own quantisation.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "nqr_renderer.h"

namespace nq::npr::classic {

struct AliasMeshVertex {
    uint32_t pose_vertex;  // vertex index within a pose
    float uv[2];
};

// Per pose and vertex, two RGBA8UI texels: (x, y, z, 0) packed position and (nx, ny, nz, 0)
// with n = (byte - 127.5) / 127.5.
inline constexpr int kPoseTexelsPerVertex = 2;

struct AliasMesh {
    std::vector<AliasMeshVertex> vertices;
    std::vector<uint32_t> indices;
    std::vector<uint8_t> pose_texels;  // num_poses x num_vertices x 2 texels x 4 bytes
};

// Checks counts and pointers; false with `error` naming the problem.
bool validate_alias_model(const nqr_alias_model& model, std::string& error);

AliasMesh build_alias_mesh(const nqr_alias_model& model);

// A triangle (model.triangles: facesfront, v0, v1, v2) whose vertices are all in range.
bool alias_triangle_valid(const nqr_alias_model& model, const int32_t* triangle);
// Whether corner 1..3 of a back-facing triangle sits on the seam (its s shifts by half a skin).
bool alias_vertex_on_back_of_seam(const nqr_alias_model& model, const int32_t* triangle,
                                  int corner);
// Texture coordinates of `vertex`, shifted by half the skin on the back of the seam.
std::array<float, 2> alias_skin_uv(const nqr_alias_model& model, uint32_t vertex,
                                   bool back_of_seam);

// Model-space unit normals of one pose (num_vertices x 3), outward for Quake's winding.
void compute_pose_normals(const nqr_alias_model& model, uint32_t pose, std::vector<float>& out);

// The packed byte (0..255) of a normal component and back.
uint8_t encode_normal_component(float value);
float decode_normal_component(uint8_t value);

}  // namespace nq::npr::classic
