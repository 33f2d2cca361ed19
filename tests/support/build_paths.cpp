#include "support/build_paths.h"

#include <cstdlib>
#include <stdexcept>

namespace nq::test {

std::string bin_dir() {
    const char* dir = std::getenv("NQ_BIN_DIR");
    if (!dir || !*dir) throw std::runtime_error("NQ_BIN_DIR is not set (run the tests via ctest)");
    return dir;
}

std::string plugin_dir() { return bin_dir() + "/plugins"; }
std::string test_plugin_dir() { return bin_dir() + "/../tests/plugins"; }

}  // namespace nq::test
