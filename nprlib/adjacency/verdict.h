// Per model: is the recovered adjacency good enough for true silhouettes and creases, or does
// the renderer fall back to the paper's thick back-face lines (which need no adjacency)?
//
// The threshold: at least 95% of the final mesh's edges manifold and consistently oriented,
// none non-manifold, and every consistency check passing. Why: a boundary edge has one face, so
// it cannot be tested for silhouette or crease and is drawn always. On LibreQuake's models the
// boundary edges are open borders (flat keys, the open backs of weapon models, bolts) and
// cracks where neighbouring parts' edges do not meet (T-junctions: 16 of knight.mdl's 89
// boundary edges, 8 of h_dog.mdl's 19); both become lines drawn from every angle. At 95% at
// most one edge in twenty is such a line, which reads as detail. Measured: closed models pass
// at 100%, monsters with a few cracks pass (ogre 95.3%, dog 96.6%, zombie 96.7%): 56 of 81
// models; the weapon models (83-93%, v_axe and v_spike excepted), the keys (84%), knight.mdl
// (89%), two heads (91%), the bolts and fish.mdl (94.9%) get the paper's back-face lines, whose
// outline needs no adjacency. Per-model figures: docs/adjacency.md. The threshold is a parameter.
#pragma once

#include <string>
#include <vector>

#include "adjacency/recovery_stats.h"

namespace nq::npr::adjacency {

inline constexpr double kMinManifoldShare = 0.95;

enum class EdgeStyle { true_edges, backface_lines };
const char* edge_style_name(EdgeStyle style);  // "true silhouettes and creases" / ...

struct Verdict {
    EdgeStyle style = EdgeStyle::backface_lines;
    std::string reason;  // one line: the figures that decided it
};

Verdict judge_adjacency(const RecoveryStats& stats, const std::vector<std::string>& problems,
                        double min_manifold_share = kMinManifoldShare);

}  // namespace nq::npr::adjacency
