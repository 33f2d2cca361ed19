#include "support/synth_wad.h"

#include "support/synth_mdl.h"  // LeWriter

namespace nq::test {

namespace {

constexpr size_t kHeaderBytes = 12;

}  // namespace

size_t synth_wad_lump_offset(const SynthWad& wad, size_t index) {
    size_t offset = kHeaderBytes;
    for (size_t i = 0; i < index; ++i) offset += wad.lumps[i].data.size();
    return offset;
}

std::vector<uint8_t> write_wad(const SynthWad& wad) {
    LeWriter w;
    const size_t dir_offset = synth_wad_lump_offset(wad, wad.lumps.size());
    w.fixed_string(wad.ident, 4);
    w.i32(wad.num_lumps.value_or(static_cast<int32_t>(wad.lumps.size())));
    w.i32(wad.dir_offset.value_or(static_cast<int32_t>(dir_offset)));
    for (const auto& lump : wad.lumps) w.bytes(lump.data);
    for (size_t i = 0; i < wad.lumps.size(); ++i) {
        const auto& lump = wad.lumps[i];
        const auto stored = static_cast<int32_t>(lump.data.size());
        w.i32(lump.file_offset.value_or(static_cast<int32_t>(synth_wad_lump_offset(wad, i))));
        w.i32(lump.disk_size.value_or(stored));
        w.i32(lump.size.value_or(stored));
        w.u8(lump.type);
        w.u8(lump.compression);
        w.u8(0);
        w.u8(0);
        w.fixed_string(lump.name, 16);
    }
    return w.take();
}

std::vector<uint8_t> write_qpic(int32_t width, int32_t height, const std::vector<uint8_t>& pixels) {
    LeWriter w;
    w.i32(width);
    w.i32(height);
    w.bytes(pixels);
    return w.take();
}

std::vector<uint8_t> gradient_pixels(size_t count, uint8_t first) {
    std::vector<uint8_t> p(count);
    for (size_t i = 0; i < count; ++i) p[i] = static_cast<uint8_t>(first + i);
    return p;
}

std::vector<uint8_t> synthetic_palette_lmp() {
    std::vector<uint8_t> p;
    for (int i = 0; i < 256; ++i) {
        p.push_back(static_cast<uint8_t>(i));
        p.push_back(static_cast<uint8_t>(255 - i));
        p.push_back(static_cast<uint8_t>(i / 2));
    }
    return p;
}

std::vector<uint8_t> synthetic_colormap_lmp(bool id_trailing_byte) {
    std::vector<uint8_t> map;
    for (int level = 0; level < 64; ++level) {
        for (int i = 0; i < 256; ++i) {
            map.push_back(static_cast<uint8_t>(i >= 224 ? i : i * (63 - level) / 63));
        }
    }
    if (id_trailing_byte) map.push_back(0);
    return map;
}

SynthWad sample_wad() {
    SynthWad wad;
    wad.lumps.push_back(
        {"NUM_0", 0x42, 0, write_qpic(24, 24, gradient_pixels(576, 7)), {}, {}, {}});
    wad.lumps.push_back({"CONCHARS", 0x44, 0, gradient_pixels(128 * 128, 0), {}, {}, {}});
    wad.lumps.push_back({"Palette", 0x40, 0, synthetic_palette_lmp(), {}, {}, {}});
    wad.lumps.push_back({"face1", 0x42, 0, write_qpic(3, 2, {1, 2, 3, 4, 5, 6}), {}, {}, {}});
    return wad;
}

std::vector<SeedFile> synthetic_wad_seeds() {
    std::vector<SeedFile> seeds;
    seeds.push_back({"sample.wad", write_wad(sample_wad())});

    SynthWad compressed = sample_wad();
    compressed.lumps[3].compression = 1;
    seeds.push_back({"compressed_lump.wad", write_wad(compressed)});

    SynthWad lying = sample_wad();
    lying.lumps[0].disk_size = 1 << 20;
    seeds.push_back({"lying_lump_size.wad", write_wad(lying)});

    SynthWad bad_pic = sample_wad();
    bad_pic.lumps[3].data = write_qpic(300, 300, {1, 2, 3});
    seeds.push_back({"truncated_pic.wad", write_wad(bad_pic)});

    seeds.push_back({"synth_pic.lmp", write_qpic(5, 3, gradient_pixels(15, 100))});
    seeds.push_back({"synth_palette.lmp", synthetic_palette_lmp()});
    seeds.push_back({"synth_colormap.lmp", synthetic_colormap_lmp(true)});
    return seeds;
}

}  // namespace nq::test
