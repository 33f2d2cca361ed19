// The models `mdltool adjacency` reads: FILE arguments as given, DIRs walked for *.mdl, and
// PAK archives (*.pak) opened for their *.mdl entries, named "ARCHIVE:entry".
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "common/result.h"

namespace nq::mdltool {

struct ModelInput {
    std::string name;
    std::function<Result<std::vector<uint8_t>>()> read;
};

struct ModelInputs {
    std::vector<ModelInput> models;   // in argument order
    std::vector<std::string> errors;  // missing paths, unreadable paks, folders without models
};

ModelInputs expand_model_inputs(const std::vector<std::string>& args);

}  // namespace nq::mdltool
