#include "support/synth_spr.h"

#include "support/synth_mdl.h"  // LeWriter

namespace nq::test {

namespace {

void write_picture(LeWriter& w, const SynthSpr::Picture& p) {
    w.i32(p.origin_x);
    w.i32(p.origin_y);
    w.i32(p.width);
    w.i32(p.height);
    w.bytes(p.pixels);
}

void write_frame(LeWriter& w, const SynthSpr::Frame& f) {
    w.i32(f.type);
    if (f.type == 1) {
        w.i32(f.group_count.value_or(static_cast<int32_t>(f.pictures.size())));
        for (float t : f.intervals) w.f32(t);
    }
    for (const auto& p : f.pictures) write_picture(w, p);
}

}  // namespace

std::vector<uint8_t> write_spr(const SynthSpr& s) {
    LeWriter w;
    w.fixed_string(s.ident, 4);
    w.i32(s.version);
    w.i32(s.type);
    w.f32(s.bounding_radius);
    w.i32(s.max_width);
    w.i32(s.max_height);
    w.i32(s.num_frames.value_or(static_cast<int32_t>(s.frames.size())));
    w.f32(s.beam_length);
    w.i32(s.sync_type);
    for (const auto& f : s.frames) write_frame(w, f);
    w.bytes(s.trailing);
    return w.take();
}

SynthSpr::Picture synth_picture(int32_t width, int32_t height, uint8_t first) {
    SynthSpr::Picture p;
    p.origin_x = -width / 2;
    p.origin_y = height / 2;
    p.width = width;
    p.height = height;
    p.pixels.resize(size_t(width) * size_t(height));
    for (size_t i = 0; i < p.pixels.size(); ++i) p.pixels[i] = static_cast<uint8_t>(first + i);
    return p;
}

SynthSpr minimal_spr() {
    SynthSpr s;
    s.frames.push_back({0, std::nullopt, {}, {synth_picture(4, 4, 1)}});
    return s;
}

SynthSpr animated_spr() {
    SynthSpr s = minimal_spr();
    s.type = 3;  // oriented
    s.sync_type = 1;
    s.frames.push_back(
        {1, std::nullopt, {0.1f, 0.25f}, {synth_picture(4, 2, 20), synth_picture(2, 4, 40)}});
    return s;
}

std::vector<SeedFile> synthetic_spr_seeds() {
    std::vector<SeedFile> seeds;
    seeds.push_back({"minimal.spr", write_spr(minimal_spr())});
    seeds.push_back({"animated.spr", write_spr(animated_spr())});

    SynthSpr lying = animated_spr();
    lying.frames[1].group_count = 5;
    seeds.push_back({"lying_group_count.spr", write_spr(lying)});

    SynthSpr huge = minimal_spr();
    huge.frames[0].pictures[0].width = 0x10000;
    seeds.push_back({"huge_picture.spr", write_spr(huge)});
    return seeds;
}

}  // namespace nq::test
