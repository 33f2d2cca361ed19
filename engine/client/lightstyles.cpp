#include "client/lightstyles.h"

#include <algorithm>
#include <cmath>

namespace nq {

void LightStyles::clear() {
    lengths_.fill(0);
}

bool LightStyles::set(int style, std::string_view pattern) {
    if (style < 0 || style >= kMaxLightStyles) return false;
    size_t n = std::min(pattern.size(), kMaxLightStylePattern);
    std::copy_n(pattern.begin(), n, patterns_[style].begin());
    lengths_[style] = static_cast<uint8_t>(n);
    return true;
}

std::string_view LightStyles::pattern(int style) const {
    if (style < 0 || style >= kMaxLightStyles) return {};
    return {patterns_[style].data(), lengths_[style]};
}

float LightStyles::value(int style, double time) const {
    if (style < 0 || style >= kMaxLightStyles || lengths_[style] == 0) return 1.0f;
    // The tiny bias keeps 0.3 * 10 (2.9999...) on letter 3, where a reader expects it.
    double step = std::floor(std::max(time, 0.0) * 10.0 + 1e-6);
    if (!std::isfinite(step)) step = 0;
    size_t index = static_cast<size_t>(std::fmod(step, static_cast<double>(lengths_[style])));
    int letter = std::clamp(patterns_[style][index] - 'a', 0, 'z' - 'a');
    return static_cast<float>(letter) / static_cast<float>('m' - 'a');
}

void LightStyles::evaluate(double time, std::span<float, kMaxLightStyles> out) const {
    for (int i = 0; i < kMaxLightStyles; ++i) out[i] = value(i, time);
}

}  // namespace nq
