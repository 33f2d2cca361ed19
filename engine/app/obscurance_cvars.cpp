#include "app/obscurance_cvars.h"

#include <string>
#include <utility>

#include "obscurance/sample_tables.h"

namespace nq {

using npr::obscurance::ComputeUse;
using npr::obscurance::DualRadius;
using npr::obscurance::ObscuranceMode;

void ObscuranceCvars::register_cvars(CvarRegistry& cvars,
                                     std::function<void(const std::string&)> warn) {
    warn_ = std::move(warn);
    const npr::obscurance::ObscuranceSettings d;
    auto flag = [&](const char* name, bool value, const char* description) {
        return cvars.register_cvar(
            {name, value ? "1" : "0", kCvarArchive, description, 0.0f, 1.0f});
    };
    auto number = [&](const char* name, const char* value, float lo, float hi,
                      const char* description) {
        return cvars.register_cvar({name, value, kCvarArchive, description, lo, hi});
    };
    cvars_[enable] = flag("vo_enable", d.enabled,
                          "volumetric obscurance (screen-space ambient occlusion) in every style");
    cvars_[mode] = cvars.register_cvar(
        {"vo_mode",
         std::string(npr::obscurance::obscurance_mode_name(d.mode)),
         kCvarArchive,
         "sampling: lines5, lines9 (Loos & Sloan line samples), points12, points33, area1 "
         "(one area sample), reference (converged lines, slow)",
         {},
         {}});
    cvars_[radius] = number("vo_radius", "24", 1.0f, 512.0f, "sphere radius in world units");
    cvars_[radius2] =
        number("vo_radius2", "0", 0.0f, 512.0f, "a second sphere radius (0 = one radius)");
    cvars_[dual] = flag("vo_dual_min", false, "two radii combine by minimum (1) or by product (0)");
    cvars_[thickness] = number("vo_thickness", "32", 0.0f, 4096.0f,
                               "occluder thickness in world units (0 = infinitely thick)");
    cvars_[strength] = number("vo_strength", "1", 0.0f, 1.0f, "0 = no darkening, 1 = all of it");
    cvars_[normal] =
        flag("vo_normal", d.normal_clamp, "clamp each sample by the surface's tangent plane");
    cvars_[shift] = flag("vo_shift", d.shift,
                         "per-pixel pattern: 1 turns and shifts the samples (every radius), 0 "
                         "only turns them (the paper)");
    cvars_[blur] = flag("vo_blur", d.blur, "edge-aware (depth and normal) blur");
    cvars_[half] = flag("vo_half", d.half_resolution, "compute at half resolution");
    cvars_[show] =
        cvars.register_cvar({"vo_show", "0", 0, "show the obscurance alone", 0.0f, 1.0f});
    cvars_[sample_set] = cvars.register_cvar(
        {"vo_sample_set",
         npr::obscurance::sample_method_name(d.sample_method),
         kCvarArchive,
         "the line and point sets: electrostatic (the paper's), poisson or lloyd (for comparison)",
         {},
         {}});
    cvars_[sample_count] =
        number("vo_sample_count", "0", 0.0f, float(npr::obscurance::kMaxPointSamples),
               "lines or points instead of the mode's count (0 = the mode's; 4, 6, 8, 10 lines "
               "and 11, 13, 32, 34 points have electrostatic sets)");
    const std::string compute_default = std::to_string(static_cast<int>(d.compute));
    cvars_[compute] = number("vo_compute", compute_default.c_str(), 0.0f, 2.0f,
                             "estimate and blur: 0 full-screen triangles, 1 compute shaders "
                             "(GL 4.3), 2 the way a short trial measures faster");
    read();
}

const npr::obscurance::ObscuranceSettings& ObscuranceCvars::settings() {
    for (size_t i = 0; i < cvars_.size(); ++i) {
        if (cvars_[i] && cvars_[i]->modified_count() != seen_[i]) {
            read();
            break;
        }
    }
    return settings_;
}

void ObscuranceCvars::read() {
    for (size_t i = 0; i < cvars_.size(); ++i) {
        if (!cvars_[i]) return;
        seen_[i] = cvars_[i]->modified_count();
    }
    npr::obscurance::ObscuranceSettings& s = settings_;
    s.enabled = cvars_[enable]->value() != 0.0f;
    if (auto parsed = npr::obscurance::parse_obscurance_mode(cvars_[mode]->string())) {
        s.mode = *parsed;
    } else {
        s.mode = ObscuranceMode::lines5;
        if (warn_) {
            warn_("vo_mode \"" + cvars_[mode]->string() +
                  "\" is not one of lines5, lines9, points12, points33, area1, reference; "
                  "using lines5");
        }
    }
    s.radius = cvars_[radius]->value();
    s.radius2 = cvars_[radius2]->value();
    s.dual = cvars_[dual]->value() != 0.0f ? DualRadius::minimum : DualRadius::product;
    s.thickness = cvars_[thickness]->value();
    s.strength = cvars_[strength]->value();
    s.normal_clamp = cvars_[normal]->value() != 0.0f;
    s.shift = cvars_[shift]->value() != 0.0f;
    s.blur = cvars_[blur]->value() != 0.0f;
    s.half_resolution = cvars_[half]->value() != 0.0f;
    s.show = cvars_[show]->value() != 0.0f;
    const float compute_use = cvars_[compute]->value();
    s.compute = compute_use >= 2.0f   ? ComputeUse::fastest
                : compute_use >= 1.0f ? ComputeUse::on
                                      : ComputeUse::off;
    if (!npr::obscurance::parse_sample_method(cvars_[sample_set]->string(), s.sample_method)) {
        s.sample_method = npr::obscurance::SampleMethod::electrostatic;
        if (warn_) {
            warn_("vo_sample_set \"" + cvars_[sample_set]->string() +
                  "\" is not one of electrostatic, poisson, lloyd; using electrostatic");
        }
    }
    s.sample_count = int(cvars_[sample_count]->value());
    if (s.sample_count > 0 && npr::obscurance::effective_sample_count(s) != s.sample_count &&
        (npr::obscurance::samples_lines(s.mode) || npr::obscurance::samples_points(s.mode)) &&
        warn_) {
        warn_("vo_sample_count " + std::to_string(s.sample_count) + ": no " +
              cvars_[sample_set]->string() + " set of that count for " +
              std::string(npr::obscurance::obscurance_mode_name(s.mode)) + "; it takes its own");
    }
}

}  // namespace nq
