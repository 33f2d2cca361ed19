// Every parameter of the screen-space volumetric obscurance pass (Loos & Sloan, "Volumetric
// Obscurance", I3D 2010), with its default. The engine fills this from its vo_* cvars
// (docs/console.md); the pass only reads it.
#pragma once

#include <optional>
#include <string_view>

#include "obscurance/sample_sets.h"

namespace nq::npr::obscurance {

// vo_mode: how the sphere around each pixel is sampled.
enum class ObscuranceMode {
    lines5,     // 5 line samples on the disk, each integrating occupancy along the sphere's depth
    lines9,     // 9 line samples
    points12,   // 12 point samples in the ball (Crytek-style baseline)
    points33,   // 33 point samples
    area1,      // 1 area sample: the mean and variance of the depths under the sphere's disk,
                // read from a mip chain of depth moments, integrated under a box model
    reference,  // 64 x 64 stratified lines, no randomisation, no blur: the converged
                // obscurance of the same depth buffer, for measuring the other modes' error
};
inline constexpr int kObscuranceModes = 6;

std::optional<ObscuranceMode> parse_obscurance_mode(std::string_view name);
std::string_view obscurance_mode_name(ObscuranceMode mode);
bool samples_lines(ObscuranceMode mode);   // lines5, lines9
bool samples_points(ObscuranceMode mode);  // points12, points33

// vo_compute 0, 1, 2: the estimate and the blur over full-screen triangles, as compute
// programs, or each the way a short trial measures to be faster on this GPU (stage_trial.h).
enum class ComputeUse { off, on, fastest };

// How two radii combine (vo_radius2 > 0): their obscurances multiplied, or the smaller taken.
enum class DualRadius { product, minimum };

struct ObscuranceSettings {
    bool enabled = false;
    ObscuranceMode mode = ObscuranceMode::lines5;
    float radius = 24.0f;  // world units (Quake units; a player is 56 tall)
    float radius2 = 0.0f;  // a second sphere (0 = none)
    DualRadius dual = DualRadius::product;
    float thickness = 32.0f;   // occluders are this thick (0 = infinitely: halos behind edges)
    float strength = 1.0f;     // 0 = no effect, 1 = the obscurance as measured
    bool normal_clamp = true;  // the tangent plane bounds each sample (flat surfaces stay open)
    // vo_shift: the per-pixel pattern also shifts every sample through the sphere's volume
    // (a Cranley-Patterson shift in coordinates that keep volume), not only turns the set, so
    // a ring of samples reaches every radius and the blurred estimate has no bias from where
    // the set's samples happen to lie.
    bool shift = true;
    bool blur = true;  // edge-aware (depth and normal) bilateral blur
    bool half_resolution = false;
    // vo_compute: how the estimate and the blur run where the context has compute shaders
    // (GL 4.3; else always over full-screen triangles). The same result every way.
    ComputeUse compute = ComputeUse::fastest;
    bool show = false;  // vo_show: the obscurance alone, in grey
    // vo_sample_set: whose line and point tables the estimate uses (sample_tables.h); the
    // paper's electrostatic sets by default, the others for the error comparison.
    SampleMethod sample_method = SampleMethod::electrostatic;
    // vo_sample_count: lines or points taken instead of the mode's own count (0 = its own), for
    // comparing the paper's counts with their neighbours; only counts with a table apply.
    int sample_count = 0;
};

// The lines or points a mode takes with these settings: vo_sample_count when the tables hold a
// set of that count for the mode's kind and vo_sample_set, otherwise the mode's own (1 for
// area1 and the reference, which take no table).
int effective_sample_count(const ObscuranceSettings& settings);

}  // namespace nq::npr::obscurance
