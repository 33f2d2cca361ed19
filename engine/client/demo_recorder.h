// Records what the client receives as a .dem file (Quake's client-side recording): the CD track
// line, then one block per message the client read — its length, the view angles at the time,
// and the message bytes. Blocks go straight to the file; nothing is held in memory.
#pragma once

#include <array>
#include <cstdint>
#include <cstdio>
#include <span>
#include <string>

namespace nq {

class DemoRecorder {
  public:
    DemoRecorder() = default;
    ~DemoRecorder() { close(); }
    DemoRecorder(const DemoRecorder&) = delete;
    DemoRecorder& operator=(const DemoRecorder&) = delete;

    // Creates `path` (truncating it) and writes the header; "" on success, else why not.
    std::string open(const std::string& path, int cd_track = -1);
    // One block; false after a write error (the recording is then closed).
    bool write_block(const std::array<float, 3>& view_angles, std::span<const uint8_t> message);
    // Finishes the file; returns its size in bytes (0 when nothing was open).
    uint64_t close();

    bool recording() const { return file_ != nullptr; }
    const std::string& path() const { return path_; }
    uint64_t blocks() const { return blocks_; }

  private:
    std::FILE* file_ = nullptr;
    std::string path_;
    uint64_t blocks_ = 0;
    uint64_t bytes_ = 0;
};

}  // namespace nq
