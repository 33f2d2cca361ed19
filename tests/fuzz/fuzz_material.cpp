// Fuzz target: per-model material files (progs/*.mdl.mat) for the illustrative style.
// Seeds: a few synthetic material files written here (valid, VMT-braced, odd, broken).
#include <string>

#include "fuzz_target.h"
#include "illustrative/material_file.h"

namespace {

nq::test::SeedFile text_seed(const std::string& name, const std::string& text) {
    return {name, std::vector<uint8_t>(text.begin(), text.end())};
}

std::vector<nq::test::SeedFile> material_seeds() {
    return {
        text_seed("vmt.mat",
                  "\"VertexLitGeneric\"\n{\n  \"$phongexponent\" \"25\"\n  $phongboost 2\n"
                  "  \"$phongfresnelranges\" \"[0.05 0.5 1]\"\n  $rimlight 1\n"
                  "  $rimlightexponent 4 // tight\n  $rimlightboost 2\n  $rimmask 1\n"
                  "  $lightwarptexture \"gfx/ramp.png\"\n  $selfillum 0\n  $ambientscale 0.5\n}\n"),
        text_seed("bare.mat", "$phongboost 3\r\n$lightwarptexture cel\r\n"),
        text_seed("odd.mat",
                  "$shiny 1\n$phongboost lots\n$rimlightboost 1e30\n$rimlight 2\n"
                  "$phongfresnelranges [1 2]\n$ambientscale\n$selfillum \"1\n}\n{{\n"),
        text_seed("empty.mat", ""),
    };
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
    nq::fuzz::handle_write_seeds(*argc, *argv, material_seeds());
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string file = "progs/fuzz.mdl.mat";
    const auto r = nq::npr::illustrative::parse_material_file({data, size}, file);
    // Read every field and message so the sanitizers see any bad value.
    size_t sink = r.error.size() + size_t(r.error_line);
    for (const auto& w : r.warnings)
        sink += nq::npr::illustrative::format_material_warning(file, w).size();
    const auto& m = r.material;
    float sum = m.phong_exponent.value_or(0) + m.phong_boost.value_or(0) +
                m.rim_light_exponent.value_or(0) + m.rim_light_boost.value_or(0) +
                m.ambient_scale.value_or(0);
    if (m.phong_fresnel_ranges) sum += (*m.phong_fresnel_ranges)[0] + (*m.phong_fresnel_ranges)[2];
    sink += size_t(m.rim_light.value_or(false)) + size_t(m.rim_mask.value_or(false)) +
            size_t(m.self_illum.value_or(false)) + m.light_warp_texture.value_or("").size();
    volatile size_t keep = sink + size_t(sum != sum);
    (void)keep;
    return 0;
}
