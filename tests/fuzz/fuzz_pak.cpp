// Fuzzes the PAK directory parser. On success every entry's data is touched, and the directory
// is written back with the engine's writer and parsed again: what the parser accepts, the
// writer must reproduce (same names, same bytes).
#include <cstring>

#include "formats/pak.h"
#include "fuzz_target.h"
#include "support/synth_pak.h"

namespace {

void check(bool ok) {
    if (!ok) __builtin_trap();
}

uint32_t touch(std::span<const uint8_t> bytes) {
    uint32_t sum = 0;
    for (uint8_t b : bytes) sum += b;
    return sum;
}

void check_round_trip(std::span<const uint8_t> data, const nq::PakDirectory& dir) {
    // Entries may all point at the same bytes; copying them could need far more memory than
    // the input, so large totals skip this check.
    uint64_t total = 0;
    for (const nq::PakEntry& e : dir.entries) total += e.size;
    if (total > (16u << 20)) return;
    std::vector<nq::PakFile> files;
    for (const nq::PakEntry& e : dir.entries) {
        auto bytes = nq::pak_entry_bytes(data, e);
        check(bytes.size() == e.size);
        files.push_back({e.name, {bytes.begin(), bytes.end()}});
    }
    auto written = nq::write_pak(files, "rewritten.pak");
    check(written.ok());
    auto reparsed = nq::parse_pak(*written, "rewritten.pak");
    check(reparsed.ok());
    check(reparsed->entries.size() == files.size());
    for (size_t i = 0; i < files.size(); ++i) {
        auto again = nq::pak_entry_bytes(*written, reparsed->entries[i]);
        check(reparsed->entries[i].name == files[i].name);
        check(again.size() == files[i].data.size());
        check(again.empty() || std::memcmp(again.data(), files[i].data.data(), again.size()) == 0);
    }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
    nq::fuzz::handle_write_seeds(*argc, *argv, nq::test::synthetic_pak_seeds());
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::span<const uint8_t> input(data, size);
    auto r = nq::parse_pak(input, "fuzz.pak");
    if (!r) return 0;
    volatile uint32_t sink = 0;
    for (const nq::PakEntry& e : r->entries) {
        sink = sink + touch(nq::pak_entry_bytes(input, e));
        sink = sink + static_cast<uint32_t>(e.name.size());
        check(nq::pak_name_problem(e.name).empty());
    }
    check_round_trip(input, *r);
    return 0;
}
