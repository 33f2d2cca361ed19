// Quake's area nodes: a fixed binary tree over the world's bounds (depth 4, 31 nodes) that halves
// the longer horizontal axis at each level. An entity sits in the deepest node whose box contains
// its abs box, on that node's solid or trigger list, so a query only visits the nodes its own box
// reaches. Lists keep insertion order (later links go last), which decides ties the way Quake's
// linked lists do. Links are indices into storage made once for every edict: linking and
// unlinking never allocate.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "vm/vm.h"

namespace nq::server {

using vm::Vec3f;

class AreaTree {
  public:
    static constexpr int kDepth = 4;
    static constexpr int kMaxNodes = 32;
    enum List : uint32_t { kSolids = 0, kTriggers = 1 };

    explicit AreaTree(uint32_t max_edicts);

    // Splits mins..maxs anew and unlinks every edict.
    void build(const Vec3f& mins, const Vec3f& maxs);
    // Puts `edict` (unlinked first) on `list` of the node that contains absmin..absmax.
    void link(uint32_t edict, const Vec3f& absmin, const Vec3f& absmax, List list);
    void unlink(uint32_t edict);
    void unlink_all();
    bool linked(uint32_t edict) const;

    // Calls visit(edict) for every edict on `list` in the nodes the box mins..maxs reaches, the
    // node's own list before its children, as Quake walks them. visit returns false to stop the
    // whole walk. It must not link or unlink while walking.
    template <class Visit>
    void walk(List list, const Vec3f& mins, const Vec3f& maxs, Visit&& visit) const {
        walk_node(0, list, mins, maxs, visit);
    }

  private:
    static constexpr uint32_t kNone = UINT32_MAX;
    struct Node {
        int axis = -1;  // 0 or 1; -1 for a leaf
        float dist = 0;
        std::array<int, 2> children{};  // [0] above dist, [1] below
    };
    struct Link {
        uint32_t prev = kNone;  // kNone: not linked
        uint32_t next = kNone;
    };

    int build_node(int depth, const Vec3f& mins, const Vec3f& maxs);
    uint32_t head(int node, List list) const { return max_edicts_ + uint32_t(node) * 2 + list; }

    template <class Visit>
    bool walk_node(int n, List list, const Vec3f& mins, const Vec3f& maxs, Visit& visit) const {
        const uint32_t h = head(n, list);
        for (uint32_t e = links_[h].next; e != h; e = links_[e].next) {
            if (!visit(e)) return false;
        }
        const Node& node = nodes_[n];
        if (node.axis < 0) return true;
        if (maxs[node.axis] > node.dist && !walk_node(node.children[0], list, mins, maxs, visit)) {
            return false;
        }
        return mins[node.axis] >= node.dist || walk_node(node.children[1], list, mins, maxs, visit);
    }

    uint32_t max_edicts_;
    std::array<Node, kMaxNodes> nodes_{};
    int node_count_ = 0;
    std::vector<Link> links_;  // max_edicts entries, then a list head per node and list
};

}  // namespace nq::server
