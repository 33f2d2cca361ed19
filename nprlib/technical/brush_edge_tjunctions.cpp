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
// Cell borders lie at 28.5 + 64 k, off the 1-unit grid maps are built on: a side on that grid
// (most are) lies inside one row of cells instead of being registered on both sides of a border.
constexpr float kCellOrigin = 28.5f;
constexpr int kCellBits = 21;  // per axis: +-2^20 cells cover any BSP2 coordinate

struct CellEntry {
    uint64_t cell;
    uint32_t item;  // a half-edge, or a piece
};

bool operator<(const CellEntry& x, const CellEntry& y) {
    return x.cell < y.cell || (x.cell == y.cell && x.item < y.item);
}

bool operator==(const CellEntry& x, const CellEntry& y) {
    return x.cell == y.cell && x.item == y.item;
}

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
    return static_cast<int>(std::floor((coordinate - kCellOrigin) / kCellSize));
}

float cell_centre(int cell) {
    return (static_cast<float>(cell) + 0.5f) * kCellSize + kCellOrigin;
}

// Sorted cell entries and, for each cell in them, where its run starts: an open-addressing
// table, so that looking a cell up costs a few integer operations.
class CellLookup {
  public:
    explicit CellLookup(std::vector<CellEntry> entries) : entries_(std::move(entries)) {
        size_t slots = 16;
        while (slots < entries_.size() * 2) slots *= 2;
        keys_.assign(slots, kEmpty);
        starts_.assign(slots, 0);
        for (size_t i = 0; i < entries_.size(); ++i) {
            if (i > 0 && entries_[i].cell == entries_[i - 1].cell) continue;
            size_t slot = slot_of(entries_[i].cell);
            while (keys_[slot] != kEmpty) slot = (slot + 1) & (keys_.size() - 1);
            keys_[slot] = entries_[i].cell;
            starts_[slot] = static_cast<uint32_t>(i);
        }
    }

    bool empty() const { return entries_.empty(); }

    // Calls visit(index) for every entry of `cell`.
    template <typename Visit>
    void for_each_in(uint64_t cell, Visit&& visit) const {
        for (size_t slot = slot_of(cell); keys_[slot] != kEmpty;
             slot = (slot + 1) & (keys_.size() - 1)) {
            if (keys_[slot] != cell) continue;
            for (size_t i = starts_[slot]; i < entries_.size() && entries_[i].cell == cell; ++i) {
                visit(entries_[i].item);
            }
            return;
        }
    }

  private:
    static constexpr uint64_t kEmpty = ~uint64_t{0};  // pack_cell never makes it
    size_t slot_of(uint64_t cell) const {
        return static_cast<size_t>((cell * 0x9E3779B97F4A7C15ull) >> 32) & (keys_.size() - 1);
    }

    std::vector<CellEntry> entries_;
    std::vector<uint64_t> keys_;
    std::vector<uint32_t> starts_;
};

void register_piece(const glm::vec3& a, const glm::vec3& b, uint32_t item,
                    std::vector<CellEntry>& out) {
    const glm::vec3 lo = glm::min(a, b) - kOnLineTolerance;
    const glm::vec3 hi = glm::max(a, b) + kOnLineTolerance;
    for (int x = cell_of(lo.x); x <= cell_of(hi.x); ++x) {
        for (int y = cell_of(lo.y); y <= cell_of(hi.y); ++y) {
            for (int z = cell_of(lo.z); z <= cell_of(hi.z); ++z) {
                out.push_back({pack_cell(x, y, z), item});
            }
        }
    }
}

// Registers the segment p0-p1 as `index`, cut into pieces no longer than a cell.
void register_segment(const glm::vec3& p0, const glm::vec3& p1, uint32_t index,
                      std::vector<CellEntry>& out) {
    const float length = glm::length(p1 - p0);
    const int pieces = std::max(1, static_cast<int>(std::ceil(length / kCellSize)));
    for (int k = 0; k < pieces; ++k) {
        register_piece(p0 + (p1 - p0) * (static_cast<float>(k) / pieces),
                       p0 + (p1 - p0) * (static_cast<float>(k + 1) / pieces), index, out);
    }
}

void sort_cells(std::vector<CellEntry>& entries) {
    std::sort(entries.begin(), entries.end());
    entries.erase(std::unique(entries.begin(), entries.end()), entries.end());
}

std::vector<CellEntry> hash_cells(const std::vector<LooseHalfEdge>& half_edges) {
    std::vector<CellEntry> entries;
    for (uint32_t i = 0; i < half_edges.size(); ++i) {
        register_segment(half_edges[i].p0, half_edges[i].p1, i, entries);
    }
    sort_cells(entries);
    return entries;
}

bool may_pair(const LooseHalfEdge& a, const LooseHalfEdge& b) {
    return a.surface != b.surface && a.component == b.component &&
           glm::dot(a.p1 - a.p0, b.p1 - b.p0) < 0.0f;
}

// A pair of indices as one sortable number (sorting these is much cheaper than sorting pairs).
uint64_t pack_pair(uint32_t a, uint32_t b) {
    return uint64_t{a} << 32 | b;
}

void sort_unique(std::vector<uint64_t>& values) {
    std::sort(values.begin(), values.end());
    values.erase(std::unique(values.begin(), values.end()), values.end());
}

// Pairs (a < b, packed) of half-edges that share a hash cell and could pair, each once.
std::vector<uint64_t> candidate_pairs(const std::vector<LooseHalfEdge>& half_edges) {
    const std::vector<CellEntry> entries = hash_cells(half_edges);
    std::vector<uint64_t> pairs;
    for (size_t begin = 0; begin < entries.size();) {
        size_t end = begin;
        while (end < entries.size() && entries[end].cell == entries[begin].cell) ++end;
        for (size_t i = begin; i < end; ++i) {
            for (size_t j = i + 1; j < end; ++j) {
                const uint32_t a = entries[i].item, b = entries[j].item;
                if (may_pair(half_edges[a], half_edges[b])) pairs.push_back(pack_pair(a, b));
            }
        }
        begin = end;
    }
    sort_unique(pairs);
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

// The parts of `wanted` that no interval in `taken` covers, longer than twice the tolerance.
std::vector<Interval> free_parts(std::vector<Interval> taken, Interval wanted) {
    std::sort(taken.begin(), taken.end(), [](Interval x, Interval y) { return x.lo < y.lo; });
    std::vector<Interval> parts;
    float reached = wanted.lo;
    for (const Interval& t : taken) {
        if (std::min(t.lo, wanted.hi) - reached > 2.0f * kOnLineTolerance) {
            parts.push_back({reached, std::min(t.lo, wanted.hi)});
        }
        reached = std::max(reached, t.hi);
    }
    if (wanted.hi - reached > 2.0f * kOnLineTolerance) parts.push_back({reached, wanted.hi});
    return parts;
}

void add_uncovered(const LooseHalfEdge& h, uint32_t index, const std::vector<Interval>& taken,
                   std::vector<UncoveredPiece>& out) {
    if (taken.empty()) {
        out.push_back({index, h.p0, h.p1});
        return;
    }
    const Line line = line_of(h);
    for (const Interval& part : free_parts(taken, {0.0f, line.length})) {
        out.push_back({index, line.origin + line.direction * part.lo,
                       line.origin + line.direction * part.hi});
    }
}

// ---- pieces across the inside of faces

// Planes closer than this (sine of the angle) are one plane: a piece there is not a crease.
constexpr float kParallelSine = 1.0e-3f;

struct FaceCandidate {
    float rotation;
    uint32_t piece, face;
    Interval on_piece;
};

// Pairs (face, piece), packed, whose cells meet. A piece inside a face lies within the tolerance
// of a point of the face, and the piece's cells were grown by the tolerance: the cells of the
// face's own bounding box that its plane passes through are enough.
std::vector<uint64_t> face_piece_pairs(const std::vector<UncoveredPiece>& pieces,
                                       const std::vector<CrossableFace>& faces,
                                       const std::vector<glm::vec3>& corners) {
    std::vector<CellEntry> entries;
    for (uint32_t i = 0; i < pieces.size(); ++i) {
        register_segment(pieces[i].from, pieces[i].to, i, entries);
    }
    sort_cells(entries);
    const CellLookup cells(std::move(entries));
    std::vector<uint64_t> pairs, of_face;
    if (cells.empty()) return pairs;
    // Half the diagonal of a cell: cells whose centre is farther from the plane miss it.
    const float reach = 0.5f * std::sqrt(3.0f) * kCellSize + kOnLineTolerance;
    for (uint32_t f = 0; f < faces.size(); ++f) {
        const CrossableFace& face = faces[f];
        if (face.num_corners < 3) continue;
        glm::vec3 lo = corners[face.first_corner], hi = lo;
        for (uint32_t c = 1; c < face.num_corners; ++c) {
            lo = glm::min(lo, corners[face.first_corner + c]);
            hi = glm::max(hi, corners[face.first_corner + c]);
        }
        of_face.clear();
        for (int x = cell_of(lo.x); x <= cell_of(hi.x); ++x) {
            for (int y = cell_of(lo.y); y <= cell_of(hi.y); ++y) {
                for (int z = cell_of(lo.z); z <= cell_of(hi.z); ++z) {
                    const float height = face.normal.x * cell_centre(x) +
                                         face.normal.y * cell_centre(y) +
                                         face.normal.z * cell_centre(z) - face.dist;
                    if (std::abs(height) > reach) continue;
                    cells.for_each_in(pack_cell(x, y, z), [&](uint32_t piece) {
                        of_face.push_back(pack_pair(f, piece));
                    });
                }
            }
        }
        sort_unique(of_face);  // a face's pairs come out together: no global sort needed
        pairs.insert(pairs.end(), of_face.begin(), of_face.end());
    }
    return pairs;
}

// The stretch of `line` (the piece) inside the face's polygon, when the face's plane holds the
// piece and is not the piece's own (`normal`), and the piece does not run along a side.
bool inside_face(const Line& line, const glm::vec3& normal, const CrossableFace& face,
                 const std::vector<glm::vec3>& corners, Interval& out) {
    if (glm::length(glm::cross(normal, face.normal)) < kParallelSine) return false;
    const glm::vec3 end = line.origin + line.direction * line.length;
    if (std::abs(glm::dot(face.normal, line.origin) - face.dist) > kOnLineTolerance ||
        std::abs(glm::dot(face.normal, end) - face.dist) > kOnLineTolerance) {
        return false;
    }
    float lo = 0.0f, hi = line.length;
    for (uint32_t c = 0; c < face.num_corners; ++c) {
        const glm::vec3& a = corners[face.first_corner + c];
        const glm::vec3& b = corners[face.first_corner + (c + 1) % face.num_corners];
        const glm::vec3 across = glm::cross(face.normal, b - a);  // into the polygon
        const float across_length = glm::length(across);
        if (across_length <= kOnLineTolerance) continue;
        const glm::vec3 inward = across / across_length;
        const float at_start = glm::dot(line.origin - a, inward);
        const float slope = glm::dot(line.direction, inward);
        const float at_end = at_start + slope * line.length;
        // Along this side: the face meets the piece with its outline, not with its inside.
        if (std::abs(at_start) <= kOnLineTolerance && std::abs(at_end) <= kOnLineTolerance) {
            return false;
        }
        if (std::abs(slope) < 1.0e-6f) {
            if (at_start < 0.0f) return false;
            continue;
        }
        const float crossing = -at_start / slope;
        if (slope > 0.0f) {
            lo = std::max(lo, crossing);
        } else {
            hi = std::min(hi, crossing);
        }
    }
    out = {lo, hi};
    return hi - lo > 2.0f * kOnLineTolerance;
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
    for (const uint64_t pair : candidate_pairs(half_edges)) {
        const auto a = static_cast<uint32_t>(pair >> 32), b = static_cast<uint32_t>(pair);
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

FaceCrossingMatching match_pieces_inside_faces(const std::vector<LooseHalfEdge>& half_edges,
                                               const std::vector<UncoveredPiece>& pieces,
                                               const std::vector<CrossableFace>& faces,
                                               const std::vector<glm::vec3>& corners) {
    std::vector<Line> lines(pieces.size());
    for (size_t i = 0; i < pieces.size(); ++i) {
        lines[i] = line_of(LooseHalfEdge{pieces[i].from, pieces[i].to});
    }
    std::vector<FaceCandidate> candidates;
    for (const uint64_t pair : face_piece_pairs(pieces, faces, corners)) {
        const auto f = static_cast<uint32_t>(pair >> 32), p = static_cast<uint32_t>(pair);
        const LooseHalfEdge& owner = half_edges[pieces[p].half_edge];
        const CrossableFace& face = faces[f];
        if (face.surface == owner.surface || face.component != owner.component) continue;
        FaceCandidate candidate{0.0f, p, f, {}};
        if (!inside_face(lines[p], owner.normal, face, corners, candidate.on_piece)) continue;
        candidate.rotation = brush_rotation_degrees(owner.normal, lines[p].direction, face.normal);
        if (std::isfinite(candidate.rotation)) candidates.push_back(candidate);
    }
    std::sort(
        candidates.begin(), candidates.end(), [](const FaceCandidate& x, const FaceCandidate& y) {
            return std::tie(x.rotation, x.piece, x.face) < std::tie(y.rotation, y.piece, y.face);
        });

    FaceCrossingMatching result;
    std::vector<std::vector<Interval>> taken(pieces.size());
    for (const FaceCandidate& c : candidates) {
        const Line& line = lines[c.piece];
        for (const Interval& part : free_parts(taken[c.piece], c.on_piece)) {
            taken[c.piece].push_back(part);
            result.matches.push_back({pieces[c.piece].half_edge, c.face,
                                      line.origin + line.direction * part.lo,
                                      line.origin + line.direction * part.hi});
        }
    }
    for (uint32_t i = 0; i < pieces.size(); ++i) {
        add_uncovered(LooseHalfEdge{pieces[i].from, pieces[i].to}, pieces[i].half_edge, taken[i],
                      result.uncovered);
    }
    return result;
}

}  // namespace nq::npr::technical
