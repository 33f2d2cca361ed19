#include "obscurance/obscurance_settings.h"

#include "obscurance/sample_tables.h"

namespace nq::npr::obscurance {

std::optional<ObscuranceMode> parse_obscurance_mode(std::string_view name) {
    for (int i = 0; i < kObscuranceModes; ++i) {
        const auto mode = static_cast<ObscuranceMode>(i);
        if (name == obscurance_mode_name(mode)) return mode;
    }
    return std::nullopt;
}

std::string_view obscurance_mode_name(ObscuranceMode mode) {
    switch (mode) {
        case ObscuranceMode::lines5:
            return "lines5";
        case ObscuranceMode::lines9:
            return "lines9";
        case ObscuranceMode::points12:
            return "points12";
        case ObscuranceMode::points33:
            return "points33";
        case ObscuranceMode::area1:
            return "area1";
        case ObscuranceMode::reference:
            return "reference";
    }
    return "lines5";
}

bool samples_lines(ObscuranceMode mode) {
    return mode == ObscuranceMode::lines5 || mode == ObscuranceMode::lines9;
}

bool samples_points(ObscuranceMode mode) {
    return mode == ObscuranceMode::points12 || mode == ObscuranceMode::points33;
}

int effective_sample_count(const ObscuranceSettings& settings) {
    // The modes' own counts, in ObscuranceMode's order (area1 and the reference take no table).
    constexpr int kOwnCount[kObscuranceModes] = {5, 9, 12, 33, 1, 1};
    const int own = kOwnCount[static_cast<int>(settings.mode)];
    if (!samples_lines(settings.mode) && !samples_points(settings.mode)) return own;
    const int wanted = settings.sample_count;
    if (wanted <= 0 || wanted == own) return own;
    const bool has_table = samples_lines(settings.mode)
                               ? !line_sample_table(settings.sample_method, wanted).empty()
                               : !point_sample_table(settings.sample_method, wanted).empty();
    return has_table ? wanted : own;
}

}  // namespace nq::npr::obscurance
