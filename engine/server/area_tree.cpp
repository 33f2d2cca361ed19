#include "server/area_tree.h"

namespace nq::server {

AreaTree::AreaTree(uint32_t max_edicts)
    : max_edicts_(max_edicts), links_(size_t(max_edicts) + kMaxNodes * 2) {
    build({0, 0, 0}, {0, 0, 0});
}

void AreaTree::build(const Vec3f& mins, const Vec3f& maxs) {
    node_count_ = 0;
    build_node(0, mins, maxs);
    unlink_all();
}

int AreaTree::build_node(int depth, const Vec3f& mins, const Vec3f& maxs) {
    const int index = node_count_++;
    Node& node = nodes_[index];
    if (depth == kDepth) {
        node.axis = -1;
        return index;
    }
    node.axis = maxs[0] - mins[0] > maxs[1] - mins[1] ? 0 : 1;
    node.dist = 0.5f * (maxs[node.axis] + mins[node.axis]);
    Vec3f upper_mins = mins, lower_maxs = maxs;
    upper_mins[node.axis] = lower_maxs[node.axis] = node.dist;
    const int upper = build_node(depth + 1, upper_mins, maxs);
    const int lower = build_node(depth + 1, mins, lower_maxs);
    nodes_[index].children = {upper, lower};
    return index;
}

void AreaTree::unlink_all() {
    for (uint32_t e = 0; e < max_edicts_; ++e) links_[e] = {};
    for (int n = 0; n < kMaxNodes; ++n) {
        for (List list : {kSolids, kTriggers}) {
            const uint32_t h = head(n, list);
            links_[h] = {h, h};  // an empty circular list
        }
    }
}

bool AreaTree::linked(uint32_t edict) const {
    return edict < max_edicts_ && links_[edict].prev != kNone;
}

void AreaTree::unlink(uint32_t edict) {
    if (!linked(edict)) return;
    Link& link = links_[edict];
    links_[link.prev].next = link.next;
    links_[link.next].prev = link.prev;
    link = {};
}

void AreaTree::link(uint32_t edict, const Vec3f& absmin, const Vec3f& absmax, List list) {
    if (edict >= max_edicts_) return;
    unlink(edict);
    int n = 0;
    // Down while the box lies wholly on one side; a box that straddles stays at this node.
    while (nodes_[n].axis >= 0) {
        const Node& node = nodes_[n];
        if (absmin[node.axis] > node.dist) {
            n = node.children[0];
        } else if (absmax[node.axis] < node.dist) {
            n = node.children[1];
        } else {
            break;
        }
    }
    const uint32_t h = head(n, list);
    const uint32_t last = links_[h].prev;
    links_[edict] = {last, h};
    links_[last].next = edict;
    links_[h].prev = edict;
}

}  // namespace nq::server
