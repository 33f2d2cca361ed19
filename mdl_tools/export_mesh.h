// Writing one pose of a recovered mesh to a file with OpenMesh's writers (format by extension).
#pragma once

#include <cstdint>
#include <string>

#include "adjacency/model_adjacency.h"
#include "nqr_renderer.h"

namespace nq::mdltool {

// File extensions OpenMesh's core writers handle here.
bool is_supported_mesh_extension(const std::string& path);

// Writes `pose` of the model; returns "" or what went wrong.
std::string write_mesh_pose(const nqr_alias_model& model,
                            const npr::adjacency::ModelAdjacency& adjacency, uint32_t pose,
                            const std::string& path);

}  // namespace nq::mdltool
