// Coloured lighting kept beside the map as maps/<name>.lit: "QLIT", int32 version 1, then an
// RGB triple for every byte of the map's lighting lump, in the same order.
#include <cstring>

#include "common/byte_reader.h"
#include "formats/bsp.h"

namespace nq {

namespace {

constexpr char kLitMagic[4] = {'Q', 'L', 'I', 'T'};
constexpr int32_t kLitVersion = 1;
constexpr size_t kLitHeaderBytes = 8;

}  // namespace

Result<BspLit> parse_lit(std::span<const uint8_t> data, const std::string& name,
                         size_t expected_samples) {
    return capture_errors(name, [&]() -> BspLit {
        ByteReader r(data, name);
        if (r.size() < kLitHeaderBytes) {
            r.fail_at(0, "truncated header: " + std::to_string(r.size()) + " bytes, a .lit " +
                             "header needs " + std::to_string(kLitHeaderBytes));
        }
        if (std::memcmp(r.bytes(4).data(), kLitMagic, sizeof kLitMagic) != 0) {
            r.fail_at(0, "not a .lit file (magic is not \"QLIT\")");
        }
        const int32_t version = r.i32();
        if (version != kLitVersion) {
            r.fail_at(4, "unsupported .lit version " + std::to_string(version) + " (expected 1)");
        }
        BspLit lit;
        const size_t payload = r.remaining();
        if (payload % 3 != 0 || payload / 3 != expected_samples) {
            lit.warnings.push_back(name + ": holds " + std::to_string(payload) + " colour bytes " +
                                   "but the map has " + std::to_string(expected_samples) +
                                   " lightmap samples (" + std::to_string(expected_samples * 3) +
                                   " bytes expected); coloured light ignored");
            return lit;
        }
        auto rgb = r.bytes(payload);
        lit.rgb.assign(rgb.begin(), rgb.end());
        return lit;
    });
}

}  // namespace nq
