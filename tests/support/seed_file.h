// A synthetic file made by our own writers: fuzz seeds and test fixtures.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace nq::test {

struct SeedFile {
    std::string name;  // file name, e.g. "minimal_bsp29.bsp"
    std::vector<uint8_t> bytes;
};

}  // namespace nq::test
