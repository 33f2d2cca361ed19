#include "technical/brush_edge_tjunctions.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec3.hpp>

namespace nq::npr::technical {
namespace {

constexpr float kCellSize = 64.0f;  // world units; most BSP sides span a few cells at most
constexpr int kCellBits = 21;       // per axis: +-2^20 cells cover any BSP2 coordinate

struct CellEntry {
    uint64_t cell;
    uint32_t half_edge;
    auto operator<=>(const CellEntry&) const = default;
};

struct Line {
    glm::vec3 origin{0.0f}, direction{0.0f};
    float length = 0.0f;
};

struct Interval {
    float lo, hi;
};

struct Candidate {
    float rotation;  // degrees: pairs that meet across the least empty space go first
    uint32_t a, b;
    Interval on_a, on_b;
    CollinearMatch match;
};

Line line_of(const LooseHalfEdge& half_edge) {
    Line line;
    line.origin = half_edge.p0;
    const glm::vec3 along = half_edge.p1 - half_edge.p0;
    line.length = glm::length(along);
    line.direction = line.length > 0.0f ? along / line.length : glm::vec3(0.0f);
    return line;
}

float parameter_on(const Line& line, const glm::vec3& point) {
    return glm::dot(point - line.origin, line.direction);
}

float distance_to_line(const Line& line, const glm::vec3& point) {
    const glm::vec3 offset = point - line.origin;
    return glm::length(offset - line.direction * glm::dot(offset, line.direction));
}

uint64_t pack_cell(int x, int y, int z) {
    constexpr uint64_t kMask = (uint64_t{1} << kCellBits) - 1;
    constexpr int64_t kBias = int64_t{1} << (kCellBits - 1);
    const auto field = [&](int v) { return static_cast<uint64_t>(v + kBias) & kMask; };
    return field(x) << (2 * kCellBits) | field(y) << kCellBits | field(z);
}

int cell_of(float coordinate) {
    return static_cast<int>(std::floor(coordinate / kCellSize));
}

void register_piece(const glm::vec3& a, const glm::vec3& b, uint32_t half_edge,
                    std::vector<CellEntry>& out) {
    const glm::vec3 lo = glm::min(a, b) - kOnLineTolerance;
    const glm::vec3 hi = glm::max(a, b) + kOnLineTolerance;
    for (int x = cell_of(lo.x); x <= cell_of(hi.x); ++x) {
        for (int y = cell_of(lo.y); y <= cell_of(hi.y); ++y) {
            for (int z = cell_of(lo.z); z <= cell_of(hi.z); ++z) {
                out.push_back({pack_cell(x, y, z), half_edge});
            }
        }
    }
}

std::vector<CellEntry> hash_cells(const std::vector<LooseHalfEdge>& half_edges) {
    std::vector<CellEntry> entries;
    for (uint32_t i = 0; i < half_edges.size(); ++i) {
        const LooseHalfEdge& h = half_edges[i];
        const float length = glm::length(h.p1 - h.p0);
        const int pieces = std::max(1, static_cast<int>(std::ceil(length / kCellSize)));
        for (int k = 0; k < pieces; ++k) {
            register_piece(h.p0 + (h.p1 - h.p0) * (static_cast<float>(k) / pieces),
                           h.p0 + (h.p1 - h.p0) * (static_cast<float>(k + 1) / pieces), i, entries);
        }
    }
    std::sort(entries.begin(), entries.end());
    entries.erase(std::unique(entries.begin(), entries.end()), entries.end());
    return entries;
}

bool may_pair(const LooseHalfEdge& a, const LooseHalfEdge& b) {
    return a.surface != b.surface && a.component == b.component &&
           glm::dot(a.p1 - a.p0, b.p1 - b.p0) < 0.0f;
}

// Pairs (a < b) of half-edges that share a hash cell and could pair, each once.
std::vector<std::pair<uint32_t, uint32_t>> candidate_pairs(
    const std::vector<LooseHalfEdge>& half_edges) {
    const std::vector<CellEntry> entries = hash_cells(half_edges);
    std::vector<std::pair<uint32_t, uint32_t>> pairs;
    for (size_t begin = 0; begin < entries.size();) {
        size_t end = begin;
        while (end < entries.size() && entries[end].cell == entries[begin].cell) ++end;
        for (size_t i = begin; i < end; ++i) {
            for (size_t j = i + 1; j < end; ++j) {
                const uint32_t a = entries[i].half_edge, b = entries[j].half_edge;
                if (may_pair(half_edges[a], half_edges[b])) pairs.emplace_back(a, b);
            }
        }
        begin = end;
    }
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    return pairs;
}

Interval interval_on(const Line& line, const glm::vec3& p, const glm::vec3& q) {
    const float s = parameter_on(line, p), t = parameter_on(line, q);
    return {std::min(s, t), std::max(s, t)};
}

// The stretch two opposite half-edges share, measured on the longer one's line (the shorter
// ones' vertices were placed on it); false when they are not collinear or barely touch.
bool overlap_of(const LooseHalfEdge& a, const LooseHalfEdge& b, uint32_t ia, uint32_t ib,
                Candidate& out) {
    const Line line_a = line_of(a), line_b = line_of(b);
    const bool a_longer = line_a.length >= line_b.length;
    const Line& longer = a_longer ? line_a : line_b;
    const LooseHalfEdge& shorter = a_longer ? b : a;
    if (distance_to_line(longer, shorter.p0) > kOnLineTolerance ||
        distance_to_line(longer, shorter.p1) > kOnLineTolerance) {
        return false;
    }
    const Interval along = interval_on(longer, shorter.p0, shorter.p1);
    const float lo = std::max(0.0f, along.lo), hi = std::min(longer.length, along.hi);
    if (hi - lo <= 2.0f * kOnLineTolerance) return false;
    const glm::vec3 start = longer.origin + longer.direction * lo;
    const glm::vec3 end = longer.origin + longer.direction * hi;
    out.a = ia;
    out.b = ib;
    out.on_a = interval_on(line_a, start, end);
    out.on_b = interval_on(line_b, start, end);
    out.match.a = ia;
    out.match.b = ib;
    // The longer line runs from start to end; a walks it that way only if a is the longer.
    out.match.from = a_longer ? start : end;
    out.match.to = a_longer ? end : start;
    out.rotation = brush_rotation_degrees(a.normal, line_a.direction, b.normal);
    return true;
}

bool overlaps_taken(const std::vector<Interval>& taken, Interval wanted) {
    for (const Interval& t : taken) {
        if (std::min(t.hi, wanted.hi) - std::max(t.lo, wanted.lo) > 2.0f * kOnLineTolerance) {
            return true;
        }
    }
    return false;
}

void add_uncovered(const LooseHalfEdge& h, uint32_t index, std::vector<Interval>& taken,
                   std::vector<UncoveredPiece>& out) {
    if (taken.empty()) {
        out.push_back({index, h.p0, h.p1});
        return;
    }
    const Line line = line_of(h);
    std::sort(taken.begin(), taken.end(), [](Interval x, Interval y) { return x.lo < y.lo; });
    float reached = 0.0f;
    const auto piece_to = [&](float until) {
        if (until - reached > 2.0f * kOnLineTolerance) {
            out.push_back({index, line.origin + line.direction * reached,
                           line.origin + line.direction * until});
        }
    };
    for (const Interval& t : taken) {
        piece_to(t.lo);
        reached = std::max(reached, t.hi);
    }
    piece_to(line.length);
}

}  // namespace

float brush_rotation_degrees(const glm::vec3& normal0, const glm::vec3& direction0,
                             const glm::vec3& normal1) {
    // Directions from the shared side into each face; face 1 walks the side the other way.
    const glm::vec3 into0 = glm::cross(normal0, direction0);
    const glm::vec3 into1 = glm::cross(normal1, -direction0);
    float degrees = glm::degrees(std::atan2(glm::dot(into1, normal0), glm::dot(into1, into0)));
    if (degrees <= 0.0f) degrees += 360.0f;
    return degrees;
}

CollinearMatching match_collinear_half_edges(const std::vector<LooseHalfEdge>& half_edges) {
    std::vector<Candidate> candidates;
    for (const auto& [a, b] : candidate_pairs(half_edges)) {
        Candidate candidate{};
        if (overlap_of(half_edges[a], half_edges[b], a, b, candidate)) {
            candidates.push_back(candidate);
        }
    }
    std::sort(candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) {
        return std::tie(x.rotation, x.a, x.b) < std::tie(y.rotation, y.a, y.b);
    });

    CollinearMatching result;
    std::vector<std::vector<Interval>> taken(half_edges.size());
    for (const Candidate& c : candidates) {
        if (overlaps_taken(taken[c.a], c.on_a) || overlaps_taken(taken[c.b], c.on_b)) continue;
        taken[c.a].push_back(c.on_a);
        taken[c.b].push_back(c.on_b);
        result.matches.push_back(c.match);
    }
    for (uint32_t i = 0; i < half_edges.size(); ++i) {
        add_uncovered(half_edges[i], i, taken[i], result.uncovered);
    }
    return result;
}

}  // namespace nq::npr::technical
