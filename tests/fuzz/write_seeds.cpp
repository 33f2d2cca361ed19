#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "common/file_io.h"
#include "fuzz_target.h"

namespace nq::fuzz {

void handle_write_seeds(int argc, char** argv, const std::vector<test::SeedFile>& seeds) {
    static const char kFlag[] = "-nq_write_seeds=";
    for (int i = 1; i < argc; ++i) {
        if (std::strncmp(argv[i], kFlag, sizeof kFlag - 1) != 0) continue;
        std::filesystem::path dir = argv[i] + sizeof kFlag - 1;
        std::error_code ec;
        std::filesystem::create_directories(dir, ec);
        for (const auto& s : seeds) {
            std::string err = write_file((dir / s.name).string(), s.bytes);
            if (!err.empty()) {
                std::fprintf(stderr, "%s\n", err.c_str());
                std::exit(1);
            }
        }
        std::printf("wrote %zu seed files to %s\n", seeds.size(), dir.c_str());
        std::exit(0);
    }
}

}  // namespace nq::fuzz
