#include "adjacency/pose_geometry.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace nq::npr::adjacency {

namespace {

FacePlane plane_through(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::vec3 n = glm::cross(b - a, c - a);  // counter-clockwise corners: outward
    const float length = glm::length(n);
    if (!(length > 0.0f)) return {};
    FacePlane plane;
    plane.normal = n / length;
    plane.distance = glm::dot(plane.normal, a);
    return plane;
}

// Angle between the normals, signed by convexity: the edge is concave when face1's far
// corner lies in front of face0's plane.
float signed_angle(const FacePlane& p0, const FacePlane& p1, const glm::vec3& far_corner1) {
    if (p0.normal == glm::vec3(0.0f) || p1.normal == glm::vec3(0.0f)) return 0.0f;
    const float angle =
        std::atan2(glm::length(glm::cross(p0.normal, p1.normal)), glm::dot(p0.normal, p1.normal));
    const float height = glm::dot(p0.normal, far_corner1) - p0.distance;
    return height > 0.0f ? -angle : angle;
}

}  // namespace

PoseGeometry compute_pose_geometry(const AliasSource& source, const BuiltMesh& built,
                                   const EdgeTable& edges) {
    PoseGeometry g;
    g.num_poses = source.num_poses();
    g.num_faces = static_cast<uint32_t>(built.face_vertices.size());
    g.num_edges = static_cast<uint32_t>(edges.edges.size());
    g.planes.resize(size_t(g.num_poses) * g.num_faces);
    g.dihedral.assign(size_t(g.num_poses) * g.num_edges, 0.0f);
    std::vector<glm::vec3> positions(built.vertex_mdl.size());
    for (uint32_t pose = 0; pose < g.num_poses; ++pose) {
        for (size_t v = 0; v < positions.size(); ++v) {
            positions[v] = source.position(pose, built.vertex_mdl[v]);
        }
        FacePlane* planes = g.planes.data() + size_t(pose) * g.num_faces;
        for (uint32_t f = 0; f < g.num_faces; ++f) {
            const auto& c = built.face_vertices[f];
            planes[f] = plane_through(positions[c[0]], positions[c[1]], positions[c[2]]);
        }
        float* dihedral = g.dihedral.data() + size_t(pose) * g.num_edges;
        for (uint32_t e = 0; e < g.num_edges; ++e) {
            const MeshEdge& edge = edges.edges[e];
            if (edge.boundary()) continue;
            dihedral[e] =
                signed_angle(planes[edge.face0], planes[edge.face1], positions[edge.opposite1]);
        }
    }
    return g;
}

}  // namespace nq::npr::adjacency
