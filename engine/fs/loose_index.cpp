#include "fs/loose_index.h"

#include <algorithm>
#include <filesystem>
#include <set>

#include "fs/vfs_path.h"

namespace nq {

namespace fs = std::filesystem;

namespace {

bool is_hidden(const fs::path& p) {
    std::string name = p.filename().string();
    return !name.empty() && name.front() == '.';
}

void sort_and_drop_case_twins(LooseScan& scan, const std::string& dir) {
    std::sort(scan.files.begin(), scan.files.end(), [](const LooseFile& a, const LooseFile& b) {
        return a.key != b.key ? a.key < b.key : a.relative < b.relative;
    });
    auto twin = [](const LooseFile& a, const LooseFile& b) { return a.key == b.key; };
    for (size_t i = 1; i < scan.files.size(); ++i) {
        if (twin(scan.files[i - 1], scan.files[i])) {
            scan.warnings.push_back(dir + ": ignoring '" + scan.files[i].relative +
                                    "', which differs only in case from '" +
                                    scan.files[i - 1].relative + "'");
        }
    }
    scan.files.erase(std::unique(scan.files.begin(), scan.files.end(), twin), scan.files.end());
}

// "pak<digits>.pak" -> the number; -1 for any other name. At most 9 digits, so no overflow.
long pak_number(const std::string& key) {
    constexpr std::string_view kPrefix = "pak", kSuffix = ".pak";
    if (key.size() <= kPrefix.size() + kSuffix.size() || !key.starts_with(kPrefix) ||
        !key.ends_with(kSuffix)) {
        return -1;
    }
    std::string digits = key.substr(kPrefix.size(), key.size() - kPrefix.size() - kSuffix.size());
    auto is_digit = [](char c) { return c >= '0' && c <= '9'; };
    if (digits.size() > 9 || !std::all_of(digits.begin(), digits.end(), is_digit)) return -1;
    return std::stol(digits);
}

}  // namespace

Result<LooseScan> scan_loose_files(const std::string& dir) {
    std::error_code ec;
    fs::recursive_directory_iterator it(dir,
                                        fs::directory_options::skip_permission_denied |
                                            fs::directory_options::follow_directory_symlink,
                                        ec);
    if (ec) return Error{dir, 0, "cannot list directory: " + ec.message()};
    LooseScan scan;
    // Directories walked, by their real path: what stops a symlink loop.
    std::set<fs::path> walked{fs::weakly_canonical(dir, ec)};
    for (; it != fs::recursive_directory_iterator(); it.increment(ec)) {
        if (ec) return Error{dir, 0, "cannot list directory: " + ec.message()};
        const fs::directory_entry& entry = *it;
        if (is_hidden(entry.path())) {
            if (entry.is_directory(ec)) it.disable_recursion_pending();
            continue;
        }
        if (entry.is_directory(ec)) {
            const fs::path real = fs::canonical(entry.path(), ec);
            if (ec || !walked.insert(real).second) {
                it.disable_recursion_pending();
                scan.warnings.push_back(
                    dir + ": not following '" +
                    entry.path().lexically_relative(dir).generic_string() + "' (it leads to " +
                    (ec ? "nowhere readable" : real.string() + ", walked already") + ")");
                ec.clear();
            }
            continue;
        }
        if (!entry.is_regular_file(ec)) continue;  // sockets, broken links
        uint64_t size = entry.file_size(ec);
        if (ec) continue;  // vanished while we walked
        std::string relative = entry.path().lexically_relative(dir).generic_string();
        scan.files.push_back(LooseFile{normalize_vfs_path(relative), relative, size});
    }
    if (ec) return Error{dir, 0, "cannot list directory: " + ec.message()};
    sort_and_drop_case_twins(scan, dir);
    return scan;
}

std::vector<const LooseFile*> numbered_paks(const LooseScan& scan) {
    std::vector<std::pair<long, const LooseFile*>> found;
    for (const LooseFile& f : scan.files) {
        if (long n = pak_number(f.key); n >= 0) found.emplace_back(n, &f);
    }
    std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) {
        return a.first != b.first ? a.first < b.first : a.second->key < b.second->key;
    });
    std::vector<const LooseFile*> out;
    for (const auto& [n, f] : found) out.push_back(f);
    return out;
}

}  // namespace nq
