// OpenMesh reports every refused face on its global error stream ("complex edge") and chats on
// its log stream while writing files. The builder expects refusals and counts them, and tools
// print their own messages, so this silences OpenMesh's streams while it lives and restores
// them after. (The streams are process-wide: build and write meshes from one thread at a time.)
#pragma once

namespace nq::npr::adjacency {

class QuietOpenMesh {
  public:
    QuietOpenMesh();
    ~QuietOpenMesh();
    QuietOpenMesh(const QuietOpenMesh&) = delete;
    QuietOpenMesh& operator=(const QuietOpenMesh&) = delete;

  private:
    bool err_was_enabled_, log_was_enabled_, out_was_enabled_;
};

}  // namespace nq::npr::adjacency
