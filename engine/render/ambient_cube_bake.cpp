#include "render/ambient_cube_bake.h"

#include <algorithm>
#include <atomic>
#include <system_error>
#include <thread>

#include "render/lightmap_probe.h"
#include "render/sphere_directions.h"

namespace nq {

namespace {

constexpr size_t kLightStyles = 64;
constexpr size_t kPointsPerTask = 32;
constexpr unsigned kMaxThreads = 16;

unsigned worker_count(unsigned wanted, size_t points) {
    unsigned n = wanted != 0 ? wanted : std::thread::hardware_concurrency();
    n = std::clamp(n, 1u, kMaxThreads);
    const size_t tasks = (points + kPointsPerTask - 1) / kPointsPerTask;
    return unsigned(std::max<size_t>(1, std::min<size_t>(n, tasks)));
}

}  // namespace

AmbientGatherer::AmbientGatherer(const Bsp& bsp, std::span<const uint8_t> rgb,
                                 std::span<const glm::vec3> reflectivity,
                                 const AmbientBakeSettings& settings)
    : bsp_(bsp),
      rgb_(rgb),
      reflectivity_(reflectivity),
      settings_(settings),
      styles_(kLightStyles, 1.0f),
      full_(make_set(settings.direction_level)),
      small_(make_set(settings.small_leaf_direction_level)) {}

AmbientGatherer::DirectionSet AmbientGatherer::make_set(int level) {
    DirectionSet set;
    set.directions = sphere_directions(level);
    for (int f = 0; f < kCubeFaces; ++f) {
        float sum = 0.0f;
        for (const glm::vec3& d : set.directions) sum += std::max(0.0f, glm::dot(d, kCubeAxes[f]));
        set.normaliser[f] = sum > 0.0f ? 1.0f / sum : 0.0f;
    }
    return set;
}

glm::vec3 AmbientGatherer::reflectivity_of(uint32_t face) const {
    const uint32_t texinfo = bsp_.faces[face].texinfo;
    if (texinfo >= bsp_.texinfo.size()) return glm::vec3(0.0f);
    const uint32_t miptex = bsp_.texinfo[texinfo].miptex;
    return miptex < reflectivity_.size() ? reflectivity_[miptex] : glm::vec3(0.0f);
}

glm::vec3 AmbientGatherer::radiance(const glm::vec3& point, const glm::vec3& direction) const {
    const auto hit =
        first_surface_along(bsp_, point, point + direction * settings_.ray_length, true);
    if (!hit) return glm::vec3(0.0f);
    const glm::vec3 albedo = reflectivity_of(hit->face);
    if (hit->sky) return settings_.sky_level * albedo;
    if (rgb_.empty()) return kUnlitSurfaceLevel * albedo;
    return sample_lightmap(bsp_, rgb_, *hit, styles_) * albedo;
}

AmbientCube AmbientGatherer::gather(const glm::vec3& point, bool small_set) const {
    const DirectionSet& set = small_set ? small_ : full_;
    AmbientCube cube;
    for (const glm::vec3& d : set.directions) {
        const glm::vec3 light = radiance(point, d);
        if (light == glm::vec3(0.0f)) continue;
        for (int f = 0; f < kCubeFaces; ++f) {
            cube.faces[f] += light * std::max(0.0f, glm::dot(d, kCubeAxes[f]));
        }
    }
    for (int f = 0; f < kCubeFaces; ++f) cube.faces[f] *= set.normaliser[f];
    return cube;
}

std::vector<AmbientSample> bake_ambient_samples(const Bsp& bsp, std::span<const uint8_t> rgb,
                                                std::span<const glm::vec3> reflectivity,
                                                const AmbientBakeSettings& settings) {
    const std::vector<AmbientSamplePoint> points =
        ambient_sample_points(bsp, settings.sample_spacing);
    std::vector<AmbientSample> samples(points.size());
    if (points.empty()) return samples;
    const AmbientGatherer gatherer(bsp, rgb, reflectivity, settings);
    std::atomic<size_t> next{0};
    auto work = [&] {
        for (size_t begin; (begin = next.fetch_add(kPointsPerTask)) < points.size();) {
            const size_t end = std::min(begin + kPointsPerTask, points.size());
            for (size_t i = begin; i < end; ++i) {
                const AmbientSamplePoint& p = points[i];
                samples[i] = {p.position, p.leaf, gatherer.gather(p.position, p.small_leaf)};
            }
        }
    };
    const unsigned n = worker_count(settings.threads, points.size());
    std::vector<std::thread> workers;
    workers.reserve(n - 1);
    for (unsigned t = 1; t < n; ++t) {
        try {
            workers.emplace_back(work);
        } catch (const std::system_error&) {
            break;  // no more threads to be had: the ones running (and this one) do the rest
        }
    }
    work();
    for (std::thread& w : workers) w.join();
    return samples;
}

}  // namespace nq
