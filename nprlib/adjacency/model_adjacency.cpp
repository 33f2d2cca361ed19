#include "adjacency/model_adjacency.h"

#include <chrono>

#include "adjacency/alias_source.h"
#include "adjacency/edge_census.h"
#include "adjacency/mesh_checks.h"
#include "adjacency/orientation.h"
#include "adjacency/triangle_filter.h"
#include "adjacency/weld.h"

namespace nq::npr::adjacency {

namespace {

std::vector<uint32_t> mdl_to_mesh(const BuiltMesh& built, uint32_t num_mdl_vertices) {
    std::vector<uint32_t> map(num_mdl_vertices, kNone);
    for (size_t f = 0; f < built.face_corners.size(); ++f) {
        for (int k = 0; k < 3; ++k) {
            uint32_t& slot = map[built.face_corners[f][k]];
            if (slot == kNone) slot = built.face_vertices[f][k];
        }
    }
    return map;
}

std::vector<std::array<uint32_t, 3>> welded_in_file_order(const std::vector<SoupTriangle>& soup) {
    std::vector<std::array<uint32_t, 3>> out;
    out.reserve(soup.size());
    for (const SoupTriangle& t : soup) out.push_back(t.welded);
    return out;
}

}  // namespace

ModelAdjacency recover_adjacency(const nqr_alias_model& model, const RecoveryOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    const AliasSource source(model);
    ModelAdjacency out;
    RecoveryStats& s = out.stats;
    s.mdl_vertices = source.num_vertices();
    s.triangles = source.num_triangles();
    s.poses = source.num_poses();

    const VertexWeld weld = weld_coincident_vertices(source);
    s.welds = weld.merged();
    if (source.num_poses() > 0) {
        s.kept_apart = weld.num_classes() - weld_in_one_pose(source, 0).num_classes();
    }
    const FilteredTriangles filtered = filter_triangles(source, weld);
    s.removed = filtered.counts;
    s.soup = census_of_indexed_triangles(welded_in_file_order(filtered.kept));

    const OrientationPlan plan = plan_orientation(filtered.kept);
    s.flipped_faces = plan.flipped_count;
    s.orientation_conflicts = plan.conflicts;

    out.mesh = build_mesh(source, weld, filtered.kept, plan);
    s.splits = out.mesh.splits;
    s.mesh = census_of_indexed_triangles(out.mesh.face_vertices);
    s.mesh_vertices = static_cast<uint32_t>(out.mesh.mesh.n_vertices());
    s.mesh_faces = static_cast<uint32_t>(out.mesh.mesh.n_faces());
    out.problems = check_mesh(out.mesh);
    out.mdl_to_mesh_vertex = mdl_to_mesh(out.mesh, source.num_vertices());

    out.edges = build_edge_table(out.mesh);
    out.file = describe_file_triangles(source, out.mesh);
    if (options.pose_geometry) out.geometry = compute_pose_geometry(source, out.mesh, out.edges);
    out.verdict = judge_adjacency(s, out.problems, options.min_manifold_share);
    s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

std::string verdict_log_line(const std::string& model_name, const Verdict& verdict) {
    return "adjacency: " + model_name + ": " + edge_style_name(verdict.style) + " (" +
           verdict.reason + ")";
}

}  // namespace nq::npr::adjacency
