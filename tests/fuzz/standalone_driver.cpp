// A small mutation-fuzzing driver with libFuzzer's command line (the subset we use), so fuzz
// targets build and run with any compiler: `fuzz_x [-max_total_time=S] [-seed=N] DIR|FILE...`.
// It runs every seed once, then mutates random seeds (bit flips, interesting integers written
// over counts and offsets, truncation, splices) until the time is up. Sanitizers, when enabled,
// report the crashes; the driver itself only counts executions.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "common/file_io.h"
#include "fuzz_target.h"

namespace {

using Bytes = std::vector<uint8_t>;

constexpr size_t kMaxInput = 4u << 20;

void add_seed(std::vector<Bytes>& corpus, const std::filesystem::path& p) {
    auto data = nq::read_file(p.string());
    if (data && data->size() <= kMaxInput) corpus.push_back(std::move(data.value()));
}

std::vector<Bytes> load_corpus(const std::vector<std::string>& paths) {
    std::vector<Bytes> corpus;
    for (const auto& path : paths) {
        std::error_code ec;
        if (std::filesystem::is_directory(path, ec)) {
            for (const auto& e : std::filesystem::recursive_directory_iterator(path, ec)) {
                if (e.is_regular_file()) add_seed(corpus, e.path());
            }
        } else {
            add_seed(corpus, path);
        }
    }
    return corpus;
}

void overwrite_int(Bytes& b, std::mt19937_64& rng) {
    static const uint32_t kInteresting[] = {0,          1,          0x7f,       0x80,
                                            0xff,       0x100,      0x7fff,     0x8000,
                                            0xffff,     0x10000,    0x7fffffff, 0x80000000u,
                                            0xffffffffu, 0xfffffffeu, 0x40000000, 4096};
    if (b.size() < 4) return;
    size_t at = (rng() % (b.size() / 4)) * 4;  // aligned: where Quake's counts and offsets live
    uint32_t v = kInteresting[rng() % std::size(kInteresting)];
    if (rng() % 4 == 0) v += static_cast<uint32_t>(rng() % 64) - 32;
    std::memcpy(&b[at], &v, 4);
}

void mutate(Bytes& b, const std::vector<Bytes>& corpus, std::mt19937_64& rng) {
    int n = 1 + static_cast<int>(rng() % 6);
    for (int i = 0; i < n; ++i) {
        switch (rng() % 7) {
            case 0:
                if (!b.empty()) b[rng() % b.size()] ^= static_cast<uint8_t>(1u << (rng() % 8));
                break;
            case 1:
                if (!b.empty()) b[rng() % b.size()] = static_cast<uint8_t>(rng());
                break;
            case 2:
            case 3: overwrite_int(b, rng); break;
            case 4:
                if (!b.empty()) b.resize(rng() % b.size());
                break;
            case 5: {  // splice a chunk of another seed in
                const Bytes& other = corpus[rng() % corpus.size()];
                if (other.empty() || b.empty()) break;
                size_t from = rng() % other.size();
                size_t len = std::min<size_t>(1 + rng() % 64, other.size() - from);
                size_t to = rng() % b.size();
                len = std::min(len, b.size() - to);
                std::memcpy(&b[to], &other[from], len);
                break;
            }
            default:
                if (b.size() < kMaxInput) b.insert(b.begin() + (b.empty() ? 0 : rng() % b.size()),
                                                   static_cast<uint8_t>(rng()));
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    LLVMFuzzerInitialize(&argc, &argv);
    double max_seconds = 10;
    uint64_t seed = std::random_device{}();
    std::vector<std::string> inputs;
    for (int i = 1; i < argc; ++i) {
        if (std::strncmp(argv[i], "-max_total_time=", 16) == 0) {
            max_seconds = std::atof(argv[i] + 16);
        } else if (std::strncmp(argv[i], "-seed=", 6) == 0) {
            seed = std::strtoull(argv[i] + 6, nullptr, 10);
        } else if (argv[i][0] == '-') {
            std::fprintf(stderr, "standalone driver: ignoring %s\n", argv[i]);
        } else {
            inputs.push_back(argv[i]);
        }
    }
    std::vector<Bytes> corpus = load_corpus(inputs);
    if (corpus.empty()) {
        std::fprintf(stderr, "standalone driver: no seed inputs found\n");
        return 1;
    }
    std::printf("standalone driver: %zu seeds, seed=%llu, %.0f s\n", corpus.size(),
                static_cast<unsigned long long>(seed), max_seconds);
    std::fflush(stdout);
    for (const auto& s : corpus) LLVMFuzzerTestOneInput(s.data(), s.size());

    std::mt19937_64 rng(seed);
    auto start = std::chrono::steady_clock::now();
    uint64_t execs = corpus.size();
    Bytes input;
    for (;;) {
        if ((execs & 15) == 0) {
            std::chrono::duration<double> t = std::chrono::steady_clock::now() - start;
            if (t.count() >= max_seconds) break;
        }
        input = corpus[rng() % corpus.size()];
        mutate(input, corpus, rng);
        LLVMFuzzerTestOneInput(input.data(), input.size());
        ++execs;
    }
    std::printf("standalone driver: done, %llu execs without a crash\n",
                static_cast<unsigned long long>(execs));
    return 0;
}
