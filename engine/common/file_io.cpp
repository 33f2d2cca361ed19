#include "common/file_io.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

namespace nq {

namespace {
struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
};
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;
}  // namespace

Result<std::vector<uint8_t>> read_file(const std::string& path) {
    FilePtr f(std::fopen(path.c_str(), "rb"));
    if (!f) return Error{path, 0, std::string("cannot open: ") + std::strerror(errno)};
    if (std::fseek(f.get(), 0, SEEK_END) != 0) return Error{path, 0, "cannot seek (not a file?)"};
    long size = std::ftell(f.get());
    if (size < 0) return Error{path, 0, "cannot determine size (not a regular file?)"};
    if (static_cast<uint64_t>(size) > kMaxFileBytes) {
        return Error{path, 0, "file is " + std::to_string(size) + " bytes, over the 1 GiB limit"};
    }
    std::rewind(f.get());
    std::vector<uint8_t> bytes(static_cast<size_t>(size));
    if (!bytes.empty() && std::fread(bytes.data(), 1, bytes.size(), f.get()) != bytes.size()) {
        return Error{path, 0, "short read"};
    }
    return bytes;
}

std::string write_file(const std::string& path, std::span<const uint8_t> bytes) {
    FilePtr f(std::fopen(path.c_str(), "wb"));
    if (!f) return path + ": cannot create: " + std::strerror(errno);
    if (!bytes.empty() && std::fwrite(bytes.data(), 1, bytes.size(), f.get()) != bytes.size()) {
        return path + ": write failed: " + std::strerror(errno);
    }
    if (std::fflush(f.get()) != 0) return path + ": write failed: " + std::strerror(errno);
    return {};
}

std::string append_file(const std::string& path, std::string_view text) {
    FilePtr f(std::fopen(path.c_str(), "ab"));
    if (!f) return path + ": cannot open for appending: " + std::strerror(errno);
    if (!text.empty() && std::fwrite(text.data(), 1, text.size(), f.get()) != text.size()) {
        return path + ": write failed: " + std::strerror(errno);
    }
    if (std::fflush(f.get()) != 0) return path + ": write failed: " + std::strerror(errno);
    return {};
}

}  // namespace nq
