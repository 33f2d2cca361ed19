// `mdltool export FILE [--frame N | --all-frames] [-o OUT.obj|.ply|.off]`: writes the recovered
// mesh (welded, split, oriented: the topology renderers use) in one frame's pose, or every
// frame as numbered files (OUT_000.obj, ...), through OpenMesh's writers, for inspection in
// Blender or MeshLab. OBJ files carry the file's texture coordinates per face corner.
#pragma once

#include <string>
#include <vector>

namespace nq::mdltool {

int run_export(const std::vector<std::string>& args);

}  // namespace nq::mdltool
