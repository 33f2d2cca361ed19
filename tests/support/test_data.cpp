#include "support/test_data.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

namespace fs = std::filesystem;

namespace nq::test {

std::string data_root() {
    if (const char* env = std::getenv("NPRQ_DATA"); env && *env) return env;
    return NQ_DEFAULT_DATA_DIR;
}

std::string lq1_dir() {
    fs::path dir = fs::path(data_root()) / "lq1";
    if (!fs::is_directory(dir)) {
        throw std::runtime_error("game data not found at " + dir.string() +
                                 " (set NPRQ_DATA to the directory that contains lq1/)");
    }
    return dir.string();
}

std::vector<std::string> lq1_files(const std::string& sub, const std::string& ext) {
    fs::path dir = fs::path(lq1_dir()) / sub;
    if (!fs::is_directory(dir)) throw std::runtime_error("missing data directory " + dir.string());
    auto lower = [](std::string s) {
        std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
        return s;
    };
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(dir)) {
        std::string name = lower(e.path().filename().string());
        if (e.is_regular_file() && name.size() > ext.size() &&
            name.compare(name.size() - ext.size(), ext.size(), lower(ext)) == 0) {
            out.push_back(e.path().string());
        }
    }
    if (out.empty()) throw std::runtime_error("no *" + ext + " files in " + dir.string());
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace nq::test
