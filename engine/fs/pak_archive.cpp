#include "fs/pak_archive.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <utility>

namespace nq {

namespace {

// Reads exactly `size` bytes at `offset`; returns "" or why it could not.
std::string read_exact_at(int fd, uint8_t* out, size_t size, uint64_t offset) {
    while (size > 0) {
        ssize_t n = ::pread(fd, out, size, static_cast<off_t>(offset));
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) return std::strerror(errno);
        if (n == 0) return "file ends early (changed since it was opened?)";
        out += n;
        size -= static_cast<size_t>(n);
        offset += static_cast<uint64_t>(n);
    }
    return {};
}

Result<std::vector<uint8_t>> read_range(int fd, const std::string& path, uint64_t offset,
                                        size_t size, const std::string& what) {
    std::vector<uint8_t> bytes(size);
    if (std::string problem = read_exact_at(fd, bytes.data(), size, offset); !problem.empty()) {
        return Error{path, offset,
                     "cannot read " + what + " (" + std::to_string(size) + " bytes): " + problem};
    }
    return bytes;
}

// Header and directory of the open pak `fd`, validated against its size.
Result<PakDirectory> read_directory(int fd, const std::string& path, uint64_t file_size) {
    size_t start_size =
        file_size < kPakHeaderSize ? static_cast<size_t>(file_size) : kPakHeaderSize;
    auto start = read_range(fd, path, 0, start_size, "pak header");
    if (!start) return start.error();
    auto header = parse_pak_header(*start, file_size, path);
    if (!header) return header.error();
    // parse_pak_header bounded dir_length by the file size and the entry limit.
    auto dir_bytes = read_range(fd, path, header->dir_offset, header->dir_length, "pak directory");
    if (!dir_bytes) return dir_bytes.error();
    return parse_pak_directory(*dir_bytes, *header, file_size, path);
}

}  // namespace

Result<PakArchive> PakArchive::open(const std::string& path) {
    int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return Error{path, 0, std::string("cannot open: ") + std::strerror(errno)};
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        ::close(fd);
        return Error{path, 0, "not a regular file"};
    }
    uint64_t size = static_cast<uint64_t>(st.st_size);
    auto dir = read_directory(fd, path, size);
    if (!dir) {
        ::close(fd);
        return dir.error();
    }
    return PakArchive(path, fd, size, std::move(dir.value()));
}

PakArchive::PakArchive(PakArchive&& other) noexcept
    : path_(std::move(other.path_)),
      fd_(std::exchange(other.fd_, -1)),
      file_size_(other.file_size_),
      dir_(std::move(other.dir_)) {}

PakArchive& PakArchive::operator=(PakArchive&& other) noexcept {
    if (this != &other) {
        close();
        path_ = std::move(other.path_);
        fd_ = std::exchange(other.fd_, -1);
        file_size_ = other.file_size_;
        dir_ = std::move(other.dir_);
    }
    return *this;
}

PakArchive::~PakArchive() {
    close();
}

void PakArchive::close() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
}

Result<std::vector<uint8_t>> PakArchive::read(const PakEntry& entry) const {
    if (fd_ < 0) return Error{path_, entry.offset, "archive is closed"};
    return read_range(fd_, path_, entry.offset, entry.size, "entry '" + entry.name + "'");
}

}  // namespace nq
