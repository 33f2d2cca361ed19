#include "raytraced_obscurance.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <thread>

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace nq::npr::obscurance {
namespace {

// Owns the Embree device and the two scenes: everything the camera sees (sky and liquids
// included), and the solid part the obscurance rays meet.
class EmbreeScenes {
  public:
    explicit EmbreeScenes(const ObscuranceScene& scene) {
        device_ = rtcNewDevice(nullptr);
        if (!device_) {
            error_ = "Embree: no device";
            return;
        }
        visible_ = build(scene, false);
        solid_ = build(scene, true);
    }
    ~EmbreeScenes() {
        if (visible_) rtcReleaseScene(visible_);
        if (solid_) rtcReleaseScene(solid_);
        if (device_) rtcReleaseDevice(device_);
    }
    EmbreeScenes(const EmbreeScenes&) = delete;
    EmbreeScenes& operator=(const EmbreeScenes&) = delete;

    const std::string& error() const { return error_; }
    RTCScene visible() const { return visible_; }
    RTCScene solid() const { return solid_; }
    // Geometry 0 of the visible scene is the solid triangles, 1 the others.
    static constexpr unsigned kSolidGeometry = 0;

  private:
    RTCScene build(const ObscuranceScene& scene, bool solid_only) {
        RTCScene built = rtcNewScene(device_);
        add_geometry(built, scene, true);
        if (!solid_only) add_geometry(built, scene, false);
        rtcCommitScene(built);
        if (rtcGetDeviceError(device_) != RTC_ERROR_NONE && error_.empty()) {
            error_ = "Embree refused the scene";
        }
        return built;
    }
    void add_geometry(RTCScene target, const ObscuranceScene& scene, bool solid) {
        size_t count = 0;
        for (const SceneTriangle& t : scene.triangles) count += t.solid == solid;
        RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* vertices = static_cast<float*>(
            rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                    3 * sizeof(float), std::max<size_t>(3 * count, 3)));
        auto* indices = static_cast<unsigned*>(
            rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                    3 * sizeof(unsigned), std::max<size_t>(count, 1)));
        size_t n = 0;
        for (const SceneTriangle& t : scene.triangles) {
            if (t.solid != solid) continue;
            for (const glm::vec3& v : {t.a, t.b, t.c}) {
                std::copy_n(glm::value_ptr(v), 3, vertices + 3 * n);
                indices[n] = unsigned(n);
                ++n;
            }
        }
        if (count == 0) {  // one degenerate triangle: Embree wants a buffer, hits nothing
            std::fill_n(vertices, 9, 0.0f);
            std::fill_n(indices, 3, 0u);
        }
        rtcCommitGeometry(geometry);
        rtcAttachGeometryByID(target, geometry, solid ? kSolidGeometry : 1u);
        rtcReleaseGeometry(geometry);
    }

    RTCDevice device_ = nullptr;
    RTCScene visible_ = nullptr, solid_ = nullptr;
    std::string error_;
};

struct Hit {
    float distance = std::numeric_limits<float>::infinity();
    unsigned geometry = RTC_INVALID_GEOMETRY_ID;
    glm::vec3 normal{0.0f};
};

Hit intersect(RTCScene scene, const glm::vec3& origin, const glm::vec3& direction, float far) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh{};
    rh.ray.org_x = origin.x;
    rh.ray.org_y = origin.y;
    rh.ray.org_z = origin.z;
    rh.ray.dir_x = direction.x;
    rh.ray.dir_y = direction.y;
    rh.ray.dir_z = direction.z;
    rh.ray.tnear = 0.0f;
    rh.ray.tfar = far;
    rh.ray.mask = ~0u;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene, &context, &rh);
    Hit hit;
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return hit;
    hit.distance = rh.ray.tfar;
    hit.geometry = rh.hit.geomID;
    hit.normal = glm::vec3(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z);
    return hit;
}

// Directions over the hemisphere around +z, even in solid angle: cos(theta) and the azimuth
// at the centres of a side x side grid.
std::vector<glm::vec3> hemisphere_directions(int side) {
    std::vector<glm::vec3> directions;
    for (int i = 0; i < side; ++i) {
        const float z = (float(i) + 0.5f) / float(side);
        const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
        for (int j = 0; j < side; ++j) {
            const float phi = 6.2831853f * (float(j) + 0.5f) / float(side);
            directions.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
        }
    }
    return directions;
}

// A fixed rotation about the normal per pixel (a hash of its position), so the grid's
// directions do not line up into patterns across the image.
float pixel_angle(uint32_t x, uint32_t y) {
    uint32_t h = x * 0x8da6b343u ^ y * 0xd8163841u;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    return 6.2831853f * float(h & 0xffffu) / 65536.0f;
}

float pixel_open(const EmbreeScenes& scenes, const glm::mat4& inverse_projection, uint32_t x,
                 uint32_t y, const ObscuranceScene& scene, const std::vector<glm::vec3>& dirs,
                 float radius) {
    const glm::vec2 ndc((float(x) + 0.5f) / float(scene.width) * 2.0f - 1.0f,
                        (float(y) + 0.5f) / float(scene.height) * 2.0f - 1.0f);
    const glm::vec4 far_point = inverse_projection * glm::vec4(ndc, 1.0f, 1.0f);
    const glm::vec3 view_dir = glm::normalize(glm::vec3(far_point) / far_point.w);
    const Hit hit = intersect(scenes.visible(), glm::vec3(0.0f), view_dir,
                              std::numeric_limits<float>::infinity());
    if (hit.geometry != EmbreeScenes::kSolidGeometry) return 1.0f;  // sky, liquid or nothing
    glm::vec3 n = glm::normalize(hit.normal);
    if (glm::dot(n, view_dir) > 0.0f) n = -n;
    const glm::vec3 p = view_dir * hit.distance + n * (1e-4f * hit.distance + 1e-3f);
    // A frame around n, turned by the pixel's angle.
    const glm::vec3 helper = std::abs(n.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0);
    glm::vec3 u = glm::normalize(glm::cross(helper, n));
    glm::vec3 v = glm::cross(n, u);
    const float angle = pixel_angle(x, y);
    const glm::vec3 u2 = std::cos(angle) * u + std::sin(angle) * v;
    v = glm::cross(n, u2);
    u = u2;
    double open = 0.0;
    for (const glm::vec3& d : dirs) {
        const glm::vec3 direction = d.x * u + d.y * v + d.z * n;
        const float reach =
            std::min(intersect(scenes.solid(), p, direction, radius).distance, radius) / radius;
        open += double(reach) * reach * reach;
    }
    return float(open / double(dirs.size()));
}

}  // namespace

RaytraceResult raytrace_obscurance(const ObscuranceScene& scene, const RaytraceOptions& options) {
    RaytraceResult result;
    EmbreeScenes scenes(scene);
    if (!scenes.error().empty()) {
        result.error = scenes.error();
        return result;
    }
    const glm::mat4 inverse_projection = glm::inverse(glm::make_mat4(scene.projection));
    const std::vector<glm::vec3> dirs =
        hemisphere_directions(std::clamp(options.directions_per_side, 1, 256));
    result.open.assign(size_t(scene.width) * scene.height, 1.0f);
    std::atomic<uint32_t> next_row{0};
    const auto work = [&] {
        for (uint32_t y = next_row++; y < scene.height; y = next_row++) {
            for (uint32_t x = 0; x < scene.width; ++x) {
                result.open[size_t(y) * scene.width + x] =
                    pixel_open(scenes, inverse_projection, x, y, scene, dirs, options.radius);
            }
        }
    };
    const unsigned threads = options.threads > 0
                                 ? unsigned(options.threads)
                                 : std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::thread> pool;
    for (unsigned i = 1; i < threads; ++i) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
    return result;
}

}  // namespace nq::npr::obscurance
