// `mdltool adjacency [--json] [--time] FILE|DIR|PAK...`: recovers each model's adjacency (as
// renderers do at load time), checks the mesh, and reports what was welded, dropped and split,
// the edge figures, the verdict, and the same figures for the 2005 paper's per-frame hashing.
// Malformed files report their error and the tool carries on; exit 1 if any input failed to
// load or any mesh failed its checks.
#pragma once

#include <string>
#include <vector>

namespace nq::mdltool {

int run_adjacency(const std::vector<std::string>& args);

}  // namespace nq::mdltool
