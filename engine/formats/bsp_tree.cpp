// The three collision hulls, and the check that makes every traversal of them finite: node and
// clipnode graphs must be acyclic and at most kMaxBspTreeDepth levels deep from any node.
//
// Why a depth check rather than "children must follow their parent": compilers do write children
// after parents, but nothing in the format requires it, and a tool that shares identical subtrees
// would point backwards without creating a cycle. A bounded depth is what the queries actually
// rely on (loops end, recursion stays shallow), so that is what is validated.
#include <algorithm>
#include <utility>

#include "formats/bsp_internal.h"

namespace nq::bsp_detail {

namespace {

// Depth-first walk over every node with an explicit stack: grey nodes are on the current path,
// so meeting one again is a cycle; a path longer than the limit fails before the stack grows.
void check_tree_depth(const std::vector<BspClipNode>& tree, const ReadContext& ctx, int lump,
                      const char* kind) {
    enum : uint8_t { kUnseen, kOnPath, kDone };
    std::vector<uint8_t> state(tree.size(), kUnseen);
    std::vector<uint16_t> depth(tree.size(), 0);
    std::vector<std::pair<uint32_t, uint8_t>> path;  // node, next child to visit
    auto fail = [&](size_t node, const std::string& problem) {
        ctx.fail_record(lump, node, std::string(kind) + " " + std::to_string(node) + " " + problem);
    };
    for (uint32_t root = 0; root < tree.size(); ++root) {
        if (state[root] != kUnseen) continue;
        state[root] = kOnPath;
        path.push_back({root, 0});
        while (!path.empty()) {
            const uint32_t node = path.back().first;
            const uint8_t next = path.back().second;
            if (next < 2) {
                ++path.back().second;
                const int32_t child = tree[node].children[next];
                if (child < 0 || state[child] == kDone) continue;
                if (state[child] == kOnPath) {
                    fail(node, "has child " + std::to_string(child) + ", which leads back to it " +
                                   "(the tree has a cycle)");
                }
                if (path.size() >= static_cast<size_t>(kBspMaxTreeDepth)) {
                    fail(path.front().first, "starts a chain deeper than " +
                                                 std::to_string(kBspMaxTreeDepth) + " levels");
                }
                state[child] = kOnPath;
                path.push_back({static_cast<uint32_t>(child), 0});
                continue;
            }
            uint16_t below = 0;
            for (int32_t child : tree[node].children) {
                if (child >= 0) below = std::max(below, depth[child]);
            }
            if (below + 1 > kBspMaxTreeDepth) {
                fail(node,
                     "starts a chain deeper than " + std::to_string(kBspMaxTreeDepth) + " levels");
            }
            depth[node] = static_cast<uint16_t>(below + 1);
            state[node] = kDone;
            path.pop_back();
        }
    }
}

// Hull 0 is the node tree with each leaf replaced by its contents.
std::vector<BspClipNode> nodes_as_clipnodes(const Bsp& bsp) {
    std::vector<BspClipNode> out(bsp.nodes.size());
    for (size_t i = 0; i < bsp.nodes.size(); ++i) {
        out[i].plane = bsp.nodes[i].plane;
        for (int side = 0; side < 2; ++side) {
            const int32_t child = bsp.nodes[i].children[side];
            out[i].children[side] = child >= 0 ? child : bsp.leafs[-(child + 1)].contents;
        }
    }
    return out;
}

}  // namespace

void build_hulls(const ReadContext& ctx) {
    Bsp& bsp = ctx.out;
    bsp.hulls[0].clipnodes = nodes_as_clipnodes(bsp);
    bsp.hulls[0].clip_mins = {0, 0, 0};
    bsp.hulls[0].clip_maxs = {0, 0, 0};
    // Hulls 1 and 2 share the clipnodes lump (read into hulls[1]); the box sizes are fixed by
    // the game: player-sized and shambler-sized.
    bsp.hulls[1].clip_mins = {-16, -16, -24};
    bsp.hulls[1].clip_maxs = {16, 16, 32};
    bsp.hulls[2].clipnodes = bsp.hulls[1].clipnodes;
    bsp.hulls[2].clip_mins = {-32, -32, -24};
    bsp.hulls[2].clip_maxs = {32, 32, 64};
    check_tree_depth(bsp.hulls[0].clipnodes, ctx, kNodes, "node");
    check_tree_depth(bsp.hulls[1].clipnodes, ctx, kClipnodes, "clipnode");
}

}  // namespace nq::bsp_detail
