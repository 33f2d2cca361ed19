#include "fs/pak_tree.h"

#include <algorithm>
#include <filesystem>
#include <limits>

#include "common/file_io.h"

namespace nq {

namespace fs = std::filesystem;

namespace {

struct FoundFile {
    std::string name;
    fs::path host_path;
    uint64_t size = 0;
};

bool same_file(const fs::path& a, const std::string& b) {
    std::error_code ec;
    return !b.empty() && fs::equivalent(a, b, ec);
}

std::string check_pak_name(const std::string& name) {
    if (std::string problem = pak_name_problem(name); !problem.empty()) {
        return "'" + name + "' cannot be stored in a pak: " + problem;
    }
    if (name.size() > kPakMaxNameLength) {
        return "'" + name + "': name is " + std::to_string(name.size()) +
               " bytes, pak names are at most " + std::to_string(kPakMaxNameLength);
    }
    return {};
}

Result<std::vector<FoundFile>> find_files(const std::string& dir, const std::string& exclude) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) return Error{dir, 0, "not a directory"};
    std::vector<FoundFile> found;
    uint64_t total = 0;
    fs::recursive_directory_iterator it(dir, ec);
    for (; !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        if (!it->is_regular_file(ec) || same_file(it->path(), exclude)) continue;
        std::string name = it->path().lexically_relative(dir).generic_string();
        if (std::string problem = check_pak_name(name); !problem.empty()) {
            return Error{it->path().string(), 0, problem};
        }
        uint64_t size = it->file_size(ec);
        if (ec) break;
        total += size;
        // Checked before reading anything, so a huge tree fails fast instead of filling memory.
        if (total > static_cast<uint64_t>(std::numeric_limits<int32_t>::max())) {
            return Error{dir, 0, "files add up to more than the pak format's 2 GiB limit"};
        }
        found.push_back(FoundFile{std::move(name), it->path(), size});
    }
    if (ec) return Error{dir, 0, "cannot list directory: " + ec.message()};
    std::sort(found.begin(), found.end(),
              [](const FoundFile& a, const FoundFile& b) { return a.name < b.name; });
    return found;
}

// True if `path` (which exists) resolves to `root` or somewhere below it.
bool resolves_inside(const fs::path& path, const fs::path& root) {
    std::error_code ec;
    fs::path real = fs::canonical(path, ec);
    if (ec) return false;
    fs::path real_root = fs::canonical(root, ec);
    if (ec) return false;
    fs::path rel = real.lexically_relative(real_root);
    return !rel.empty() && *rel.begin() != "..";
}

}  // namespace

Result<std::vector<PakFile>> collect_pak_files(const std::string& dir, const std::string& exclude) {
    auto found = find_files(dir, exclude);
    if (!found) return found.error();
    std::vector<PakFile> files;
    files.reserve(found->size());
    for (FoundFile& f : found.value()) {
        auto bytes = read_file(f.host_path.string());
        if (!bytes) return bytes.error();
        files.push_back(PakFile{std::move(f.name), std::move(bytes.value())});
    }
    return files;
}

std::string extract_pak_entry(const PakArchive& pak, const PakEntry& entry,
                              const std::string& out_dir) {
    if (std::string problem = pak_name_problem(entry.name); !problem.empty()) {
        return "refusing to extract '" + entry.name + "': " + problem;
    }
    fs::path target = fs::path(out_dir) / entry.name;
    std::error_code ec;
    fs::create_directories(target.parent_path(), ec);
    if (ec) return target.parent_path().string() + ": cannot create directory: " + ec.message();
    // A symlink planted in the tree (by an earlier entry or by hand) must not redirect us.
    if (!resolves_inside(target.parent_path(), out_dir) || fs::is_symlink(target, ec)) {
        return "refusing to extract '" + entry.name + "': " + target.string() +
               " would lie outside " + out_dir + " (symlink in the way)";
    }
    auto bytes = pak.read(entry);
    if (!bytes) return bytes.error().to_string();
    return write_file(target.string(), *bytes);
}

}  // namespace nq
