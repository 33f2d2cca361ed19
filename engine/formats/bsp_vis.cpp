// Potentially visible sets. Each world leaf's row is a bit set over leafs 1..visleafs (leaf 0,
// the solid leaf, has no bit), compressed by run-length coding only zero bytes: a non-zero byte
// stands for itself, a 0 byte is followed by how many zero bytes it stands for.
#include <algorithm>

#include "formats/bsp_internal.h"

namespace nq {

namespace {

// Decodes one row starting at `offset` into `out` (row_bytes long, zero-filled). Zero runs reaching
// beyond the row are cut at the row's end. Returns false when the compressed data ends before the
// row is complete; nothing past `data` is read.
bool decode_row(std::span<const uint8_t> data, size_t offset, size_t row_bytes, uint8_t* out) {
    size_t in = offset;
    size_t produced = 0;
    while (produced < row_bytes) {
        if (in >= data.size()) return false;
        const uint8_t byte = data[in++];
        if (byte != 0) {
            out[produced] = byte;
            ++produced;
            continue;
        }
        if (in >= data.size()) return false;
        const size_t zeros = data[in++];
        produced += std::min(zeros, row_bytes - produced);  // zeros are already in `out`
    }
    return true;
}

// A row with every world leaf visible, and the padding bits of the last byte clear.
std::vector<uint8_t> all_visible_row(const Bsp& bsp) {
    std::vector<uint8_t> row(pvs_row_bytes(bsp), 0xff);
    const uint32_t leafs = bsp.models.empty() ? 0 : bsp.models[0].visleafs;
    if (leafs % 8 != 0) row.back() = static_cast<uint8_t>((1u << (leafs % 8)) - 1);
    return row;
}

}  // namespace

size_t pvs_row_bytes(const Bsp& bsp) {
    return bsp.models.empty() ? 0 : (size_t{bsp.models[0].visleafs} + 7) / 8;
}

std::vector<uint8_t> decompress_vis(const Bsp& bsp, uint32_t leaf) {
    if (leaf == 0 || leaf >= bsp.leafs.size()) return std::vector<uint8_t>(pvs_row_bytes(bsp), 0);
    const int32_t offset = bsp.leafs[leaf].vis_offset;
    if (offset < 0) return all_visible_row(bsp);
    std::vector<uint8_t> row(pvs_row_bytes(bsp), 0);
    decode_row(bsp.visibility, static_cast<size_t>(offset), row.size(), row.data());
    return row;
}

bool pvs_contains(std::span<const uint8_t> row, uint32_t leaf) {
    if (leaf == 0) return false;
    const uint32_t bit = leaf - 1;
    return bit / 8 < row.size() && (row[bit / 8] & (1u << (bit % 8))) != 0;
}

namespace bsp_detail {

namespace {

// For every position p of the visibility data: how many row bytes a walk starting at p can
// produce before the data ends (capped at `cap`). A walk's steps are fixed by where it stands,
// so walks from different offsets merge and one backward pass answers every leaf; checking each
// row by walking it would cost leafs x row bytes, which a hostile file can make huge.
std::vector<uint32_t> producible_bytes(std::span<const uint8_t> data, uint32_t cap) {
    std::vector<uint32_t> can(data.size() + 2, 0);
    for (size_t p = data.size(); p-- > 0;) {
        uint64_t total = 0;
        if (data[p] != 0) {
            total = 1 + uint64_t{can[p + 1]};
        } else if (p + 1 < data.size()) {
            total = uint64_t{data[p + 1]} + can[p + 2];
        }  // else: a run marker with no count byte produces nothing
        can[p] = static_cast<uint32_t>(std::min<uint64_t>(total, cap));
    }
    return can;
}

}  // namespace

void validate_vis_rows(const ReadContext& ctx) {
    const Bsp& bsp = ctx.out;
    const auto row_bytes = static_cast<uint32_t>(pvs_row_bytes(bsp));  // visleafs < 2^32
    if (row_bytes == 0) return;
    const std::vector<uint32_t> can = producible_bytes(bsp.visibility, row_bytes);
    for (size_t i = 1; i < bsp.leafs.size(); ++i) {
        const int32_t offset = bsp.leafs[i].vis_offset;  // -1 or within [0, size], see read_leafs
        if (offset < 0 || can[static_cast<size_t>(offset)] >= row_bytes) continue;
        const uint64_t at = ctx.file.absolute(ctx.lumps[kVisibility].offset) + offset;
        throw FormatError(Error{ctx.file.file(), at,
                                "PVS row of leaf " + std::to_string(i) + " (visibility offset " +
                                    std::to_string(offset) + ", " + std::to_string(row_bytes) +
                                    " bytes decompressed) runs past the end of the visibility " +
                                    "lump (" + std::to_string(bsp.visibility.size()) + " bytes)"});
    }
}

}  // namespace bsp_detail

}  // namespace nq
