#include "render/ambient_cube_field.h"

#include <algorithm>
#include <array>
#include <limits>

namespace nq {

namespace {

constexpr float kSightSlack = 1.0f;  // a trace that stops this close to the sample reaches it

float smoothstep01(float x) {
    x = std::clamp(x, 0.0f, 1.0f);
    return x * x * (3.0f - 2.0f * x);
}

std::vector<glm::vec3> positions_of(const std::vector<AmbientSample>& samples) {
    std::vector<glm::vec3> out;
    out.reserve(samples.size());
    for (const AmbientSample& s : samples) out.push_back(s.position);
    return out;
}

}  // namespace

float ambient_sample_weight(float distance) {
    if (!(distance < kBlendRadius)) return 0.0f;
    const float window = smoothstep01((kBlendRadius - distance) / (0.5f * kBlendRadius));
    const float d = distance / kBlendScale;
    return window / (d * d + 1.0f);
}

AmbientCubeField::AmbientCubeField(const Bsp& bsp, std::vector<AmbientSample> samples)
    : bsp_(&bsp), samples_(std::move(samples)) {
    const std::vector<glm::vec3> points = positions_of(samples_);
    grid_ = PointGrid(points, kBlendRadius);
}

AmbientCubeField AmbientCubeField::bake(const Bsp& bsp, std::span<const uint8_t> rgb,
                                        std::span<const glm::vec3> reflectivity,
                                        const AmbientBakeSettings& settings) {
    return AmbientCubeField(bsp, bake_ambient_samples(bsp, rgb, reflectivity, settings));
}

// The kMaxBlendedSamples heaviest samples within the radius, heaviest first; their count.
int AmbientCubeField::heaviest_near(const glm::vec3& point, Weighted* out) const {
    int count = 0;
    auto offer = [&](uint32_t index) {
        const float w = ambient_sample_weight(glm::length(samples_[index].position - point));
        if (!(w > 0.0f)) return;
        if (count == kMaxBlendedSamples && w <= out[count - 1].weight) return;
        int at = count < kMaxBlendedSamples ? count++ : count - 1;
        while (at > 0 && out[at - 1].weight < w) {
            out[at] = out[at - 1];
            --at;
        }
        out[at] = {index, w};
    };
    // The grid's cells are at least kBlendRadius wide: rings 0 and 1 hold every sample in it.
    for (int ring = 0; ring <= 1; ++ring) grid_.for_each_in_ring(point, ring, offer);
    return count;
}

bool AmbientCubeField::sees(const glm::vec3& point, const AmbientSample& sample) const {
    const BspTrace t = trace_hull(*bsp_, 0, {point.x, point.y, point.z},
                                  {sample.position.x, sample.position.y, sample.position.z});
    if (t.start_solid) return false;
    return (1.0f - t.fraction) * glm::length(sample.position - point) <= kSightSlack;
}

bool AmbientCubeField::nearest_fallback(const glm::vec3& point, AmbientCube& out) const {
    float best = std::numeric_limits<float>::infinity();
    uint32_t nearest = 0;
    auto offer = [&](uint32_t index) {
        const float d = glm::length(samples_[index].position - point);
        if (d < best) {
            best = d;
            nearest = index;
        }
    };
    // Ring by ring outward; a nearer sample may still sit in the ring after the first that
    // holds one, so that one is searched too.
    int last = kFallbackRings;
    for (int ring = 0; ring <= last; ++ring) {
        grid_.for_each_in_ring(point, ring, offer);
        if (std::isfinite(best) && last > ring + 1) last = ring + 1;
    }
    if (!std::isfinite(best)) return false;
    out = samples_[nearest].cube;
    return true;
}

bool AmbientCubeField::cube_at(const glm::vec3& point, AmbientCube& out) const {
    out = AmbientCube{};
    if (samples_.empty() || !bsp_) return false;
    std::array<Weighted, kMaxBlendedSamples> near{};
    const int count = heaviest_near(point, near.data());
    float total = 0.0f;
    for (int i = 0; i < count; ++i) {
        const AmbientSample& s = samples_[near[i].sample];
        if (!sees(point, s)) continue;
        for (int f = 0; f < kCubeFaces; ++f) out.faces[f] += s.cube.faces[f] * near[i].weight;
        total += near[i].weight;
    }
    if (total > 0.0f) {
        for (glm::vec3& face : out.faces) face /= total;
        return true;
    }
    out = AmbientCube{};
    return nearest_fallback(point, out);
}

}  // namespace nq
