// The model cache's file reader over the engine's virtual filesystem. Header-only, so nq_render
// itself does not depend on nq_fs; whoever includes this links nq_fs (the engine does).
#pragma once

#include <string>

#include "fs/vfs.h"
#include "render/model_cache.h"

namespace nq {

// `vfs` must outlive the reader.
inline ModelCache::FileReader vfs_file_reader(const Vfs& vfs) {
    return [&vfs](const std::string& path) { return vfs.read(path); };
}

}  // namespace nq
