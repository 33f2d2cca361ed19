// The texture (miptex) lump: int32 count, count int32 offsets from the lump start, and at each
// offset a miptex: 16-byte name, uint32 width and height, four uint32 offsets (from the miptex
// start) of the mip levels, level i being (width >> i) x (height >> i) palette indices.
#include <string>

#include "formats/bsp_internal.h"

namespace nq::bsp_detail {

namespace {

constexpr size_t kMiptexHeaderBytes = 40;
constexpr int32_t kMaxTextures = 65536;  // far above any compiler's limit; bounds memory
constexpr uint32_t kPlaceholderSize = 16;
constexpr uint8_t kPlaceholderDark = 0;     // palette black
constexpr uint8_t kPlaceholderBright = 15;  // palette near-white

BspTexture make_placeholder(std::string name) {
    BspTexture t;
    t.name = std::move(name);
    t.width = t.height = kPlaceholderSize;
    t.placeholder = true;
    for (int level = 0; level < kBspMipLevels; ++level) {
        BspMipLevel& mip = t.mips[level];
        mip.width = mip.height = kPlaceholderSize >> level;
        const uint32_t square = mip.width / 2;  // a 2x2 checkerboard at every level
        mip.pixels.resize(size_t{mip.width} * mip.height);
        for (uint32_t y = 0; y < mip.height; ++y) {
            for (uint32_t x = 0; x < mip.width; ++x) {
                const bool odd = ((x / square) + (y / square)) % 2 != 0;
                mip.pixels[y * mip.width + x] = odd ? kPlaceholderBright : kPlaceholderDark;
            }
        }
    }
    return t;
}

// Reads the four mip levels of a miptex whose header passed its checks. `budget` is the pixel
// data still unclaimed in the lump: levels of distinct textures never share bytes in a real
// file, so more claimed pixels than the lump holds means lying offsets (and would let a small
// file allocate without bound).
void read_mip_levels(const ByteReader& miptex, const std::array<uint32_t, 4>& offsets,
                     BspTexture& t, uint64_t& budget) {
    for (int level = 0; level < kBspMipLevels; ++level) {
        BspMipLevel& mip = t.mips[level];
        mip.width = t.width >> level;
        mip.height = t.height >> level;
        const uint64_t bytes = uint64_t{mip.width} * mip.height;
        const size_t field = 24 + 4 * static_cast<size_t>(level);
        const std::string what = "texture '" + t.name + "' mip level " + std::to_string(level);
        if (offsets[level] > miptex.size() || bytes > miptex.size() - offsets[level]) {
            miptex.fail_at(field, what + " [" + std::to_string(offsets[level]) + ", +" +
                                      std::to_string(bytes) + ") lies outside the texture lump");
        }
        if (bytes > budget) {
            miptex.fail_at(field, what + ": textures claim more pixel data than the texture " +
                                      "lump holds (miptex data overlaps)");
        }
        budget -= bytes;
        auto pixels = miptex.sub(offsets[level], static_cast<size_t>(bytes), what).bytes(bytes);
        mip.pixels.assign(pixels.begin(), pixels.end());
    }
}

BspTexture read_miptex(const ByteReader& lump, size_t entry_pos, int32_t offset, size_t index,
                       uint64_t& budget, std::vector<std::string>& warnings) {
    const std::string slot = "texture " + std::to_string(index);
    if (offset == -1) {  // what compilers write for a texture they did not find
        warnings.push_back(slot + " has no miptex (offset -1); using a placeholder");
        return make_placeholder("missing");
    }
    if (offset < 0 || static_cast<size_t>(offset) > lump.size() ||
        lump.size() - static_cast<size_t>(offset) < kMiptexHeaderBytes) {
        lump.fail_at(entry_pos, slot + " miptex offset " + std::to_string(offset) +
                                    " lies outside the texture lump (" +
                                    std::to_string(lump.size()) + " bytes)");
    }
    auto miptex = lump.sub(static_cast<size_t>(offset), lump.size() - offset, slot + " miptex");
    BspTexture t;
    t.name = miptex.fixed_string(16);
    t.width = miptex.u32();
    t.height = miptex.u32();
    std::array<uint32_t, 4> offsets;
    for (uint32_t& o : offsets) o = miptex.u32();

    const std::string label = slot + " '" + t.name + "'";
    if (t.width == 0 || t.height == 0) {
        warnings.push_back(label + " has size " + std::to_string(t.width) + "x" +
                           std::to_string(t.height) + "; using a placeholder");
        return make_placeholder(t.name);
    }
    if (offsets == std::array<uint32_t, 4>{}) {  // header only: pixels live in a WAD
        warnings.push_back(label + " has no pixel data in the map; using a placeholder");
        return make_placeholder(t.name);
    }
    if (t.width % 16 != 0 || t.height % 16 != 0) {
        warnings.push_back(label + " size " + std::to_string(t.width) + "x" +
                           std::to_string(t.height) +
                           " is not a multiple of 16; smaller mip levels are rounded down");
    }
    read_mip_levels(miptex, offsets, t, budget);
    return t;
}

}  // namespace

void read_textures(const ReadContext& ctx) {
    auto r = ctx.lump_reader(kTextures);
    if (r.size() == 0) return;  // a map may carry no textures at all
    const int32_t count = r.i32();
    if (count < 0 || count > kMaxTextures) {
        r.fail_at(0, "texture count " + std::to_string(count) + " is implausible (0.." +
                         std::to_string(kMaxTextures) + ")");
    }
    r.require_records(count, 4, "miptex offsets");
    auto& textures = ctx.out.textures;
    textures.reserve(static_cast<size_t>(count));
    uint64_t budget = r.size();
    for (int32_t i = 0; i < count; ++i) {
        const size_t at = r.tell();
        const int32_t offset = r.i32();
        textures.push_back(
            read_miptex(r, at, offset, static_cast<size_t>(i), budget, ctx.out.warnings));
    }
}

}  // namespace nq::bsp_detail
