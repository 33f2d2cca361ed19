#include "obscurance/sample_sets.h"

#include <cmath>
#include <cstddef>

#include "obscurance/electrostatic.h"
#include "obscurance/lloyd_relax.h"
#include "obscurance/poisson_disk.h"

namespace nq::npr::obscurance {

namespace {

// Limits that keep a mistyped number from running for days or exhausting memory.
constexpr int kMaxCount = 1024;
constexpr int kMaxResolution = 4096;
constexpr int kMaxRestarts = 100000;
constexpr int kMaxIterations = 100000;

std::string check_range(const char* name, long long value, long long low, long long high) {
    if (value >= low && value <= high) return {};
    return std::string(name) + " must be in [" + std::to_string(low) + ", " + std::to_string(high) +
           "], not " + std::to_string(value);
}

template <class Enum>
struct NamedValue {
    const char* name;
    Enum value;
};

constexpr NamedValue<SampleKind> kKindNames[] = {
    {"lines", SampleKind::lines},
    {"points", SampleKind::points},
};

constexpr NamedValue<SampleMethod> kMethodNames[] = {
    {"electrostatic", SampleMethod::electrostatic},
    {"lloyd", SampleMethod::lloyd},
    {"poisson", SampleMethod::poisson},
};

template <class Enum, size_t N>
bool find_by_name(const NamedValue<Enum> (&names)[N], std::string_view name, Enum& value) {
    for (const NamedValue<Enum>& named : names) {
        if (name == named.name) {
            value = named.value;
            return true;
        }
    }
    return false;
}

template <class Enum, size_t N>
const char* name_of(const NamedValue<Enum> (&names)[N], Enum value) {
    for (const NamedValue<Enum>& named : names) {
        if (named.value == value) return named.name;
    }
    return "?";
}

}  // namespace

bool parse_sample_kind(std::string_view name, SampleKind& kind) {
    return find_by_name(kKindNames, name, kind);
}

bool parse_sample_method(std::string_view name, SampleMethod& method) {
    return find_by_name(kMethodNames, name, method);
}

const char* sample_kind_name(SampleKind kind) {
    return name_of(kKindNames, kind);
}

const char* sample_method_name(SampleMethod method) {
    return name_of(kMethodNames, method);
}

int effective_resolution(const GenerationParams& params, SampleKind kind) {
    if (params.resolution != 0) return params.resolution;
    return kind == SampleKind::lines ? kDefaultLineResolution : kDefaultPointResolution;
}

std::string validate(const GenerationParams& params) {
    const std::string errors[] = {
        check_range("count", params.count, 1, kMaxCount),
        check_range("restarts", params.restarts, 1, kMaxRestarts),
        params.resolution == 0 ? std::string()
                               : check_range("resolution", params.resolution, 2, kMaxResolution),
        check_range("lloyd iterations", params.lloyd_iterations, 0, kMaxIterations),
        check_range("electrostatic rounds", params.electrostatic_rounds, 1, kMaxIterations),
        check_range("repulsion steps", params.repulsion_steps, 0, kMaxIterations),
    };
    for (const std::string& error : errors) {
        if (!error.empty()) return error;
    }
    if (!(params.centroid_pull >= 0.0 && params.centroid_pull <= 1.0)) {
        return "centroid pull must be in [0, 1]";
    }
    if (params.boundary_strengths.empty()) return "no boundary strength to try";
    for (double strength : params.boundary_strengths) {
        if (!(strength >= 0.0 && std::isfinite(strength))) {
            return "boundary strengths must be finite and not negative";
        }
    }
    return {};
}

GenerationResult<LineSampleSet> generate_line_samples(SampleMethod method,
                                                      const GenerationParams& params) {
    switch (method) {
        case SampleMethod::electrostatic:
            return electrostatic_lines(params);
        case SampleMethod::lloyd:
            return lloyd_relax_lines(params);
        case SampleMethod::poisson:
            return poisson_disk_lines(params);
    }
    return GenerationResult<LineSampleSet>::failure("unknown sample method");
}

GenerationResult<PointSampleSet> generate_point_samples(SampleMethod method,
                                                        const GenerationParams& params) {
    switch (method) {
        case SampleMethod::electrostatic:
            return electrostatic_points(params);
        case SampleMethod::lloyd:
            return lloyd_relax_points(params);
        case SampleMethod::poisson:
            return poisson_disk_points(params);
    }
    return GenerationResult<PointSampleSet>::failure("unknown sample method");
}

}  // namespace nq::npr::obscurance
