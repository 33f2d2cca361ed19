// What the technical style pays per alias model when it registers one: the wall time of
// AliasEdgeMesh::create (adjacency recovery and the edge records it draws from; best of
// --repeat runs) and the heap it keeps afterwards, with the peak heap of the build above what
// it keeps. Heap bytes are counted by this program's own operator new/delete, so the figures
// need no hook in the library and the same program measures an older build (bench script:
// demos/bench_technical_models.sh --base).
//
// usage: bench_technical_models [--repeat N] DIR|FILE.mdl...
// Prints one line per model and a total line:
//   total models=N create_ms=T kept_kib=K peak_kib=P
#include <malloc.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <new>
#include <string>
#include <vector>

#include "formats/mdl.h"
#include "render/alias_model.h"
#include "technical/alias_edge_mesh.h"

namespace {

std::atomic<long long> g_live{0};
std::atomic<long long> g_peak{0};

void note_allocation(void* p) {
    if (!p) return;
    const long long now = g_live += static_cast<long long>(malloc_usable_size(p));
    long long peak = g_peak.load();
    while (now > peak && !g_peak.compare_exchange_weak(peak, now)) {
    }
}

}  // namespace

void* operator new(std::size_t size) {
    void* p = std::malloc(size ? size : 1);
    if (!p) throw std::bad_alloc();
    note_allocation(p);
    return p;
}
void* operator new[](std::size_t size) {
    return operator new(size);
}
void operator delete(void* p) noexcept {
    if (p) g_live -= static_cast<long long>(malloc_usable_size(p));
    std::free(p);
}
void operator delete[](void* p) noexcept {
    operator delete(p);
}
void operator delete(void* p, std::size_t) noexcept {
    operator delete(p);
}
void operator delete[](void* p, std::size_t) noexcept {
    operator delete(p);
}

namespace {

struct Cost {
    double create_ms = 0.0;
    long long kept = 0, peak = 0;
};

bool measure(const std::string& path, int repeat, Cost& cost, std::string& error) {
    std::ifstream in(path, std::ios::binary);
    const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                     std::istreambuf_iterator<char>());
    auto mdl = nq::parse_mdl(bytes, path);
    if (!mdl) {
        error = mdl.error().to_string();
        return false;
    }
    const auto data = nq::AliasModelData::build(std::move(*mdl));
    double best = 1e30;
    for (int r = 0; r < repeat; ++r) {
        const long long before = g_live.load();
        g_peak = before;
        const auto start = std::chrono::steady_clock::now();
        auto mesh = nq::npr::technical::AliasEdgeMesh::create(data->abi(), error);
        const auto end = std::chrono::steady_clock::now();
        if (!mesh) return false;
        best = std::min(best, std::chrono::duration<double, std::milli>(end - start).count());
        cost.kept = g_live.load() - before;
        cost.peak = g_peak.load() - before;
    }
    cost.create_ms = best;
    return true;
}

std::vector<std::string> model_files(const std::vector<std::string>& args) {
    std::vector<std::string> out;
    for (const std::string& arg : args) {
        if (!std::filesystem::is_directory(arg)) {
            out.push_back(arg);
            continue;
        }
        std::vector<std::string> found;
        for (const auto& entry : std::filesystem::recursive_directory_iterator(arg)) {
            if (entry.path().extension() == ".mdl") found.push_back(entry.path().string());
        }
        std::sort(found.begin(), found.end());
        out.insert(out.end(), found.begin(), found.end());
    }
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    int repeat = 5;
    std::vector<std::string> args;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--repeat" && i + 1 < argc) {
            repeat = std::max(1, std::atoi(argv[++i]));
        } else {
            args.push_back(arg);
        }
    }
    const std::vector<std::string> files = model_files(args);
    if (files.empty()) {
        std::fprintf(stderr, "usage: bench_technical_models [--repeat N] DIR|FILE.mdl...\n");
        return 2;
    }
    Cost total;
    int models = 0, failed = 0;
    for (const std::string& file : files) {
        Cost cost;
        std::string error;
        if (!measure(file, repeat, cost, error)) {
            std::fprintf(stderr, "%s: %s\n", file.c_str(), error.c_str());
            ++failed;
            continue;
        }
        std::printf("%s create_ms=%.3f kept_kib=%.1f peak_kib=%.1f\n", file.c_str(), cost.create_ms,
                    cost.kept / 1024.0, cost.peak / 1024.0);
        ++models;
        total.create_ms += cost.create_ms;
        total.kept += cost.kept;
        total.peak = std::max(total.peak, cost.peak);
    }
    std::printf("total models=%d create_ms=%.2f kept_kib=%.1f peak_kib=%.1f\n", models,
                total.create_ms, total.kept / 1024.0, total.peak / 1024.0);
    return failed ? 1 : 0;
}
