// Expanding command-line FILE|DIR arguments into the model files to process.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace nq::mdltool {

struct PathExpansion {
    std::vector<std::string> files;   // in argument order; each directory's files sorted
    std::vector<std::string> errors;  // "PATH: does not exist" and the like
};

// Files are taken as given; directories are walked recursively for names ending in
// `extension` (case-insensitive, e.g. ".mdl"). A directory with no match is an error.
PathExpansion expand_model_paths(const std::vector<std::string>& args, std::string_view extension);

}  // namespace nq::mdltool
