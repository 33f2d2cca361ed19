#include "obscurance/obscurance_settings.h"

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

}  // namespace nq::npr::obscurance
