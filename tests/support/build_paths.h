// Where the build put executables and plugins, for tests that run or load them. ctest sets
// NQ_BIN_DIR (build/<preset>/bin); a missing variable is a loud failure.
#pragma once

#include <string>

namespace nq::test {

std::string bin_dir();          // build/<preset>/bin
std::string plugin_dir();       // build/<preset>/bin/plugins (the real renderer plugins)
std::string test_plugin_dir();  // build/<preset>/tests/plugins (misbehaving test plugins)

}  // namespace nq::test
