#include "technical/shadow_mesh.h"

#include <algorithm>
#include <cmath>

#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModNormalFlippingT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>

namespace nq::npr::technical {
namespace {

using adjacency::TriMesh;

std::vector<std::array<uint32_t, 3>> faces_in_mdl_vertices(const TriMesh& mesh,
                                                           OpenMesh::VPropHandleT<uint32_t> mdl) {
    std::vector<std::array<uint32_t, 3>> out;
    out.reserve(mesh.n_faces());
    for (const auto face : mesh.faces()) {
        if (mesh.has_face_status() && mesh.status(face).deleted()) continue;
        std::array<uint32_t, 3> corners{};
        int k = 0;
        for (const auto vertex : mesh.fv_range(face)) {
            if (k < 3) corners[k] = mesh.property(mdl, vertex);
            ++k;
        }
        const bool degenerate =
            corners[0] == corners[1] || corners[1] == corners[2] || corners[2] == corners[0];
        if (k == 3 && !degenerate) out.push_back(corners);
    }
    return out;
}

}  // namespace

std::vector<std::array<uint32_t, 3>> shadow_triangles(const adjacency::BuiltMesh& built) {
    TriMesh mesh = built.mesh;
    OpenMesh::VPropHandleT<uint32_t> mdl;
    mesh.add_property(mdl);
    for (const auto vertex : mesh.vertices()) {
        const size_t i = static_cast<size_t>(vertex.idx());
        mesh.property(mdl, vertex) = i < built.vertex_mdl.size() ? built.vertex_mdl[i] : 0;
    }
    const size_t faces = mesh.n_faces();
    if (faces > kShadowKeepAll) {
        mesh.request_vertex_status();
        mesh.request_edge_status();
        mesh.request_halfedge_status();
        mesh.request_face_status();
        mesh.request_face_normals();
        mesh.update_face_normals();
        OpenMesh::Decimater::DecimaterT<TriMesh> decimater(mesh);
        OpenMesh::Decimater::ModQuadricT<TriMesh>::Handle quadric;
        OpenMesh::Decimater::ModNormalFlippingT<TriMesh>::Handle no_flips;
        decimater.add(quadric);
        decimater.add(no_flips);
        decimater.module(quadric).unset_max_err();
        if (decimater.initialize()) {
            const auto target = static_cast<size_t>(
                std::max<double>(kShadowKeepAll, std::ceil(double(faces) * kShadowTriangleShare)));
            decimater.decimate_to_faces(0, target);
        }
    }
    return faces_in_mdl_vertices(mesh, mdl);
}

}  // namespace nq::npr::technical
