#include "support/synth_wav.h"

#include <cstring>

namespace nq::test {
namespace {

void put_u16(std::vector<uint8_t>& out, uint32_t v) {
    out.push_back(uint8_t(v));
    out.push_back(uint8_t(v >> 8));
}
void put_u32(std::vector<uint8_t>& out, uint32_t v) {
    put_u16(out, v & 0xffff);
    put_u16(out, v >> 16);
}
void put_id(std::vector<uint8_t>& out, const char* id) {
    for (int i = 0; i < 4; ++i) out.push_back(uint8_t(id[i]));
}

void put_chunk(std::vector<uint8_t>& out, const char* id, const std::vector<uint8_t>& body,
               std::optional<uint32_t> size_field = std::nullopt) {
    put_id(out, id);
    put_u32(out, size_field.value_or(uint32_t(body.size())));
    out.insert(out.end(), body.begin(), body.end());
    if (body.size() & 1) out.push_back(0);
}

std::vector<uint8_t> fmt_body(const SynthWav& w) {
    std::vector<uint8_t> b;
    const uint32_t block = uint32_t(w.channels) * (w.bits / 8u);
    put_u16(b, w.format);
    put_u16(b, w.channels);
    put_u32(b, w.rate);
    put_u32(b, w.rate * block);
    put_u16(b, block);
    put_u16(b, w.bits);
    return b;
}

std::vector<uint8_t> data_body(const SynthWav& w) {
    std::vector<uint8_t> b;
    for (int16_t s : w.samples) {
        if (w.bits == 8) {
            b.push_back(uint8_t((s >> 8) + 128));
        } else {
            put_u16(b, uint16_t(s));
        }
    }
    return b;
}

std::vector<uint8_t> cue_body(uint32_t loop_start) {
    std::vector<uint8_t> b;
    put_u32(b, 1);  // one cue point
    put_u32(b, 1);  // its name
    put_u32(b, 0);  // position
    put_id(b, "data");
    put_u32(b, 0);  // chunk start
    put_u32(b, 0);  // block start
    put_u32(b, loop_start);
    return b;
}

std::vector<uint8_t> list_body(uint32_t loop_length) {
    std::vector<uint8_t> b;
    put_id(b, "adtl");
    put_id(b, "ltxt");
    put_u32(b, 20);  // ltxt size
    put_u32(b, 1);   // cue point name
    put_u32(b, loop_length);
    put_id(b, "mark");
    put_u16(b, 0);  // country, language, dialect, code page
    put_u16(b, 0);
    put_u16(b, 0);
    put_u16(b, 0);
    return b;
}

}  // namespace

std::vector<uint8_t> write_wav(const SynthWav& w) {
    std::vector<uint8_t> body;
    put_id(body, "WAVE");
    if (w.write_fmt) put_chunk(body, "fmt ", fmt_body(w));
    if (w.loop_start) put_chunk(body, "cue ", cue_body(*w.loop_start));
    if (w.loop_length) put_chunk(body, "LIST", list_body(*w.loop_length));
    put_chunk(body, "data", data_body(w), w.data_size);
    std::vector<uint8_t> out;
    put_id(out, "RIFF");
    put_u32(out, uint32_t(body.size()));
    out.insert(out.end(), body.begin(), body.end());
    return out;
}

std::vector<SeedFile> synthetic_wav_seeds() {
    SynthWav base;
    for (int i = 0; i < 64; ++i) base.samples.push_back(int16_t((i * 997) % 20000 - 10000));
    std::vector<SeedFile> seeds;
    seeds.push_back({"mono16.wav", write_wav(base)});
    SynthWav eight = base;
    eight.bits = 8;
    seeds.push_back({"mono8.wav", write_wav(eight)});
    SynthWav looped = base;
    looped.loop_start = 16;
    looped.loop_length = 32;
    seeds.push_back({"looped.wav", write_wav(looped)});
    SynthWav stereo = base;
    stereo.channels = 2;
    stereo.rate = 22050;
    seeds.push_back({"stereo.wav", write_wav(stereo)});
    SynthWav lying = base;
    lying.data_size = 0x7ffffff0;
    seeds.push_back({"lying_size.wav", write_wav(lying)});
    std::vector<uint8_t> cut = write_wav(looped);
    cut.resize(cut.size() / 2);
    seeds.push_back({"cut.wav", cut});
    return seeds;
}

}  // namespace nq::test
