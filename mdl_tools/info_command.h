// `mdltool info [--json] FILE|DIR...`: describes each alias model; malformed files report
// their error (file, offset, problem) and the tool carries on, exiting 1 at the end.
#pragma once

#include <string>
#include <vector>

namespace nq::mdltool {

int run_info(const std::vector<std::string>& args);

}  // namespace nq::mdltool
