// A pak file on disk: its directory is read once when opened, entry data is read on demand.
// Holds its own file descriptor (no global state); reads use pread, so concurrent const reads
// from several threads, and several archives on the same file, are safe.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "common/result.h"
#include "formats/pak.h"

namespace nq {

class PakArchive {
  public:
    static Result<PakArchive> open(const std::string& path);

    PakArchive(PakArchive&& other) noexcept;
    PakArchive& operator=(PakArchive&& other) noexcept;
    PakArchive(const PakArchive&) = delete;
    PakArchive& operator=(const PakArchive&) = delete;
    ~PakArchive();

    const std::string& path() const { return path_; }
    uint64_t file_size() const { return file_size_; }
    const PakDirectory& directory() const { return dir_; }
    const std::vector<PakEntry>& entries() const { return dir_.entries; }
    const std::vector<std::string>& warnings() const { return dir_.warnings; }

    // The data of one of this archive's entries. Fails if the file shrank since it was opened.
    Result<std::vector<uint8_t>> read(const PakEntry& entry) const;

  private:
    PakArchive(std::string path, int fd, uint64_t file_size, PakDirectory dir)
        : path_(std::move(path)), fd_(fd), file_size_(file_size), dir_(std::move(dir)) {}
    void close();

    std::string path_;
    int fd_ = -1;
    uint64_t file_size_ = 0;
    PakDirectory dir_;
};

}  // namespace nq
