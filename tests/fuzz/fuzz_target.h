// What every fuzz target defines. A target is built either against libFuzzer (fuzz preset) or
// against standalone_driver.cpp; both call LLVMFuzzerInitialize first, where a target handles
// -nq_write_seeds=DIR by writing its synthetic seed files (made by our own writers) and exiting.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "support/seed_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);
extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv);

namespace nq::fuzz {

// Call from LLVMFuzzerInitialize: if argv holds -nq_write_seeds=DIR, writes `seeds` there and
// exits the process with status 0 (or 1 on a write error).
void handle_write_seeds(int argc, char** argv, const std::vector<test::SeedFile>& seeds);

}  // namespace nq::fuzz
