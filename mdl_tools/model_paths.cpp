#include "model_paths.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace fs = std::filesystem;

namespace nq::mdltool {

namespace {

bool has_extension(const fs::path& path, std::string_view extension) {
    const std::string name = path.filename().string();
    if (name.size() < extension.size()) return false;
    return std::equal(extension.begin(), extension.end(), name.end() - extension.size(),
                      [](char a, char b) {
                          return std::tolower(static_cast<unsigned char>(a)) ==
                                 std::tolower(static_cast<unsigned char>(b));
                      });
}

void walk_directory(const std::string& dir, std::string_view extension, PathExpansion& out) {
    std::vector<std::string> found;
    std::error_code ec;
    for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        if (it->is_regular_file(ec) && has_extension(it->path(), extension)) {
            found.push_back(it->path().string());
        }
    }
    if (ec) out.errors.push_back(dir + ": cannot walk directory: " + ec.message());
    if (found.empty() && !ec) {
        out.errors.push_back(dir + ": no *" + std::string(extension) + " files found");
    }
    std::sort(found.begin(), found.end());
    out.files.insert(out.files.end(), found.begin(), found.end());
}

}  // namespace

PathExpansion expand_model_paths(const std::vector<std::string>& args, std::string_view extension) {
    PathExpansion out;
    for (const std::string& arg : args) {
        std::error_code ec;
        if (fs::is_directory(arg, ec)) {
            walk_directory(arg, extension, out);
        } else if (fs::exists(arg, ec)) {
            out.files.push_back(arg);
        } else {
            out.errors.push_back(arg + ": no such file or directory");
        }
    }
    return out;
}

}  // namespace nq::mdltool
