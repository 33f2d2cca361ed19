#include "export_mesh.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include <OpenMesh/Core/IO/MeshIO.hh>

#include "adjacency/alias_source.h"
#include "adjacency/quiet_openmesh.h"

namespace nq::mdltool {

namespace {

using npr::adjacency::TriMesh;

std::string lowercase_extension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

void set_pose_points(TriMesh& mesh, const npr::adjacency::ModelAdjacency& adjacency,
                     const npr::adjacency::AliasSource& source, uint32_t pose) {
    for (const auto v : mesh.vertices()) {
        const glm::vec3 p = source.position(pose, adjacency.mesh.vertex_mdl[v.idx()]);
        mesh.set_point(v, TriMesh::Point(p.x, p.y, p.z));
    }
}

// Texture coordinates of the file per face corner (OpenMesh keeps them per halfedge: the
// coordinate of the halfedge's target vertex in its face), as OBJ's u, v in 0..1 with v up.
void set_corner_texcoords(TriMesh& mesh, const nqr_alias_model& model,
                          const npr::adjacency::ModelAdjacency& adjacency) {
    mesh.request_halfedge_texcoords2D();
    const auto& built = adjacency.mesh;
    const float width = float(std::max(model.skin_width, 1));
    const float height = float(std::max(model.skin_height, 1));
    for (const auto f : mesh.faces()) {
        const bool faces_front = model.triangles[4 * built.face_triangle[f.idx()]] != 0;
        for (const auto h : mesh.fh_range(f)) {
            const uint32_t v = uint32_t(mesh.to_vertex_handle(h).idx());
            for (int k = 0; k < 3; ++k) {
                if (built.face_vertices[f.idx()][k] != v) continue;
                const int32_t* st = model.st + 3 * built.face_corners[f.idx()][k];
                // Quake: a back-facing triangle's on-seam vertices use the skin's right half.
                const float s = float(st[1]) + (st[0] && !faces_front ? width / 2 : 0.0f);
                mesh.set_texcoord2D(h, TriMesh::TexCoord2D((s + 0.5f) / width,
                                                           1.0f - (float(st[2]) + 0.5f) / height));
            }
        }
    }
}

}  // namespace

bool is_supported_mesh_extension(const std::string& path) {
    const std::string ext = lowercase_extension(path);
    return ext == ".obj" || ext == ".ply" || ext == ".off";
}

std::string write_mesh_pose(const nqr_alias_model& model,
                            const npr::adjacency::ModelAdjacency& adjacency, uint32_t pose,
                            const std::string& path) {
    const npr::adjacency::AliasSource source(model);
    if (pose >= source.num_poses()) return path + ": the model has no pose " + std::to_string(pose);
    TriMesh mesh = adjacency.mesh.mesh;
    set_pose_points(mesh, adjacency, source, pose);
    OpenMesh::IO::Options options;
    if (lowercase_extension(path) == ".obj" && model.st && model.triangles) {
        set_corner_texcoords(mesh, model, adjacency);
        options += OpenMesh::IO::Options::FaceTexCoord;
    }
    const npr::adjacency::QuietOpenMesh quiet;
    if (!OpenMesh::IO::write_mesh(mesh, path, options)) return path + ": cannot write mesh";
    return "";
}

}  // namespace nq::mdltool
