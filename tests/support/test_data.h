// Locating the game data for tests. Missing data is a loud failure, never a silent skip.
#pragma once

#include <string>
#include <vector>

namespace nq::test {

// Base directory holding game directories (default ../shared/data; NPRQ_DATA overrides).
std::string data_root();
// The LibreQuake game directory, data_root()/lq1. Throws std::runtime_error naming the path
// and the override variable if it does not exist, so every test that needs it fails loudly.
std::string lq1_dir();
// Full paths of the files in lq1_dir()/<sub> whose names end with `ext` (case-insensitive),
// sorted. Throws if the directory is missing or holds no such file.
std::vector<std::string> lq1_files(const std::string& sub, const std::string& ext);

}  // namespace nq::test
