#include "adjacency_report.h"

#include <cstdio>
#include <filesystem>
#include <string>

namespace nq::mdltool {

namespace {

using npr::adjacency::EdgeCensus;
using npr::adjacency::EdgeStyle;

EdgeCensus& operator+=(EdgeCensus& a, const EdgeCensus& b) {
    a.edges += b.edges;
    a.zero_length += b.zero_length;
    a.boundary += b.boundary;
    a.manifold += b.manifold;
    a.consistent += b.consistent;
    a.non_manifold += b.non_manifold;
    return a;
}

std::string short_name(const std::string& name) {
    const size_t colon = name.rfind(':');
    const std::string tail = colon == std::string::npos ? name : name.substr(colon + 1);
    return std::filesystem::path(tail).filename().string();
}

std::string format(const char* pattern, auto... values) {
    char line[256];
    std::snprintf(line, sizeof line, pattern, values...);
    return line;
}

constexpr const char* kRowFormat =
    "%-12s %5u %5u %4u %5u %5u %4u %5u %6u %5u %5u %3u %6.1f %6.1f %6.1f %6.1f %4u  %s";

std::string verdict_word(EdgeStyle style) {
    return style == EdgeStyle::true_edges ? "true" : "lines";
}

void census_json(JsonWriter& json, const char* key, const EdgeCensus& c) {
    json.key(key).begin_object();
    json.field("edges", c.edges).field("boundary", c.boundary).field("manifold", c.manifold);
    json.field("consistent", c.consistent).field("non_manifold", c.non_manifold);
    json.field("zero_length", c.zero_length).field("consistent_share", c.consistent_share());
    json.end_object();
}

}  // namespace

void AdjacencyTotals::add(const ModelReport& r) {
    const auto& s = r.stats;
    ++models;
    true_edges += r.verdict.style == EdgeStyle::true_edges;
    checks_failed += !r.problems.empty();
    triangles += s.triangles;
    degenerate += s.removed.degenerate();
    duplicates += s.removed.duplicates();
    welds += s.welds;
    kept_apart += s.kept_apart;
    flipped += s.flipped_faces;
    splits += s.splits.new_vertices;
    poses += r.paper.poses;
    soup += s.soup;
    mesh += s.mesh;
    paper_first_pose += r.paper.first_pose;
    recovery_seconds += s.seconds;
    paper_seconds += r.paper.seconds;
}

void print_table_header(std::ostream& out, bool timing) {
    // Group labels over their columns: non-manifold edges, consistent shares, the paper.
    out << std::string(67, ' ') << "nonmanif  consistent %  paper's hashing\n";
    out << format("%-12s %5s %5s %4s %5s %5s %4s %5s %6s %5s %5s %3s %6s %6s %6s %6s %4s  %s",
                  "model", "tris", "degen", "dup", "welds", "apart", "flip", "split", "edges",
                  "bound", "soup", "out", "soup", "mesh", "frame0", "worst", "nm", "verdict");
    out << (timing ? "     ms  paper ms/frame\n" : "\n");
}

void print_table_row(std::ostream& out, const ModelReport& r, bool timing) {
    const auto& s = r.stats;
    out << format(kRowFormat, short_name(r.name).c_str(), s.triangles, s.removed.degenerate(),
                  s.removed.duplicates(), s.welds, s.kept_apart, s.flipped_faces,
                  s.splits.new_vertices, s.mesh.edges, s.mesh.boundary, s.soup.non_manifold,
                  s.mesh.non_manifold, 100.0 * s.soup.consistent_share(),
                  100.0 * s.mesh.consistent_share(), 100.0 * r.paper.first_pose.consistent_share(),
                  100.0 * r.paper.worst_pose.consistent_share(), r.paper.first_pose.non_manifold,
                  verdict_word(r.verdict.style).c_str());
    if (timing) {
        const double per_frame = r.paper.poses ? r.paper.seconds / r.paper.poses : 0.0;
        out << format(" %7.3f %7.3f", s.seconds * 1e3, per_frame * 1e3);
    }
    out << (r.problems.empty() ? "" : "  CHECKS FAILED") << "\n";
}

void print_totals(std::ostream& out, const AdjacencyTotals& t, bool timing) {
    out << format(
        "%-12s %5llu %5llu %4llu %5llu %5llu %4llu %5llu %6u %5u %5u %3u %6.1f %6.1f "
        "%6.1f %6s %4u  %zu/%zu true",
        "total", (unsigned long long)t.triangles, (unsigned long long)t.degenerate,
        (unsigned long long)t.duplicates, (unsigned long long)t.welds,
        (unsigned long long)t.kept_apart, (unsigned long long)t.flipped,
        (unsigned long long)t.splits, t.mesh.edges, t.mesh.boundary, t.soup.non_manifold,
        t.mesh.non_manifold, 100.0 * t.soup.consistent_share(), 100.0 * t.mesh.consistent_share(),
        100.0 * t.paper_first_pose.consistent_share(), "", t.paper_first_pose.non_manifold,
        t.true_edges, t.models);
    out << "\n";
    out << "consistency checks: " << (t.models - t.checks_failed) << "/" << t.models
        << " models passed\n";
    if (timing) {
        const double per_frame = t.poses ? t.paper_seconds / double(t.poses) : 0.0;
        out << format(
            "time: weld + adjacency for %zu models %.1f ms in total (one thread); the "
            "paper's per-frame hashing %.3f ms per model per frame on average\n",
            t.models, t.recovery_seconds * 1e3, per_frame * 1e3);
    }
}

void print_legend(std::ostream& out) {
    out << "columns:\n"
           "  tris     triangles in the file\n"
           "  degen    dropped: repeated index, collapsed by the weld, or no area in any frame\n"
           "  dup      dropped: exact duplicates and back-to-back twins\n"
           "  welds    MDL vertices merged into another (same packed position in every frame)\n"
           "  apart    merges a frame-0 weld would make that later frames tear apart (refused)\n"
           "  flip     faces reoriented to agree with their neighbours\n"
           "  split    vertices added to keep the mesh manifold\n"
           "  edges    edges of the final mesh; bound: those with one face\n"
           "  nonmanif edges with three or more faces: welded soup, final mesh\n"
           "  consistent %  edges manifold and consistently oriented: welded soup (file\n"
           "           orientation), final mesh\n"
           "  paper's hashing  the 2005 method: consistent % in frame 0 and in its worst frame,\n"
           "           non-manifold edges in frame 0\n"
           "  verdict  true: true silhouettes and creases; lines: back-face lines\n"
           "  ms, paper ms/frame (--time)  recovery per model; the paper's hashing per frame\n";
}

void write_model_json(JsonWriter& json, const ModelReport& r) {
    const auto& s = r.stats;
    json.begin_object().field("path", r.name).field("ok", true);
    json.field("vertices", s.mdl_vertices).field("triangles", s.triangles).field("poses", s.poses);
    json.key("removed").begin_object();
    json.field("repeated_index", s.removed.repeated_index)
        .field("collapsed_by_weld", s.removed.collapsed_by_weld)
        .field("zero_area", s.removed.zero_area)
        .field("exact_duplicates", s.removed.exact_duplicates)
        .field("back_to_back_twins", s.removed.back_to_back_twins)
        .field("bad_index", s.removed.bad_index);
    json.end_object();
    json.field("welds", s.welds).field("kept_apart", s.kept_apart);
    json.field("flipped_faces", s.flipped_faces)
        .field("orientation_conflicts", s.orientation_conflicts);
    json.key("splits").begin_object();
    json.field("complex_edge_faces", s.splits.complex_edge_faces)
        .field("complex_vertex_faces", s.splits.complex_vertex_faces)
        .field("deferred_faces", s.splits.deferred_faces)
        .field("island_faces", s.splits.island_faces)
        .field("fan_splits", s.splits.fan_splits)
        .field("new_vertices", s.splits.new_vertices);
    json.end_object();
    json.field("mesh_vertices", s.mesh_vertices).field("mesh_faces", s.mesh_faces);
    census_json(json, "soup", s.soup);
    census_json(json, "mesh", s.mesh);
    json.field("checks_passed", r.problems.empty());
    json.key("problems").begin_array();
    for (const std::string& p : r.problems) json.value(p);
    json.end_array();
    json.key("verdict").begin_object();
    json.field("style", r.verdict.style == EdgeStyle::true_edges ? "true_edges" : "backface_lines");
    json.field("reason", r.verdict.reason).end_object();
    json.key("paper").begin_object().field("poses", r.paper.poses);
    census_json(json, "first_pose", r.paper.first_pose);
    census_json(json, "worst_pose", r.paper.worst_pose);
    json.field("worst_pose_index", r.paper.worst_pose_index)
        .field("poses_unlike_first", r.paper.poses_unlike_first)
        .field("seconds", r.paper.seconds);
    json.end_object();
    json.field("seconds", s.seconds);
    json.end_object();
}

void write_totals_json(JsonWriter& json, const AdjacencyTotals& t) {
    json.key("totals").begin_object();
    json.field("models", uint64_t(t.models)).field("true_edges", uint64_t(t.true_edges));
    json.field("checks_failed", uint64_t(t.checks_failed));
    json.field("triangles", t.triangles).field("degenerate", t.degenerate);
    json.field("duplicates", t.duplicates).field("welds", t.welds);
    json.field("kept_apart", t.kept_apart).field("flipped_faces", t.flipped);
    json.field("new_vertices", t.splits).field("poses", t.poses);
    census_json(json, "soup", t.soup);
    census_json(json, "mesh", t.mesh);
    census_json(json, "paper_first_pose", t.paper_first_pose);
    json.field("recovery_seconds", t.recovery_seconds).field("paper_seconds", t.paper_seconds);
    json.end_object();
}

}  // namespace nq::mdltool
