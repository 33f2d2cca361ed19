#include "obscurance/scene_file.h"

#include <cmath>
#include <cstring>

namespace nq::npr::obscurance {
namespace {

constexpr char kMagic[8] = {'N', 'Q', 'V', 'O', 'S', 'C', 'N', '1'};
constexpr size_t kHeaderSize = 8 + 4 + 4 + 16 * 4 + 4;
constexpr size_t kTriangleSize = 9 * 4 + 4;
constexpr uint32_t kSolid = 1u;

void put_u32(std::vector<uint8_t>& out, uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(uint8_t(v >> (8 * i)));
}
void put_f32(std::vector<uint8_t>& out, float f) {
    uint32_t v = 0;
    std::memcpy(&v, &f, 4);
    put_u32(out, v);
}
void put_vec3(std::vector<uint8_t>& out, const glm::vec3& v) {
    for (int i = 0; i < 3; ++i) put_f32(out, v[i]);
}

class Reader {
  public:
    Reader(std::span<const uint8_t> bytes, const std::string& file) : bytes_(bytes), file_(file) {}
    uint32_t u32() {
        uint32_t v = 0;
        for (int i = 0; i < 4; ++i) v |= uint32_t(bytes_[offset_ + size_t(i)]) << (8 * i);
        offset_ += 4;
        return v;
    }
    // A finite float, or an error naming its offset.
    bool f32(float& out, std::string& error) {
        const size_t at = offset_;
        const uint32_t v = u32();
        std::memcpy(&out, &v, 4);
        if (std::isfinite(out)) return true;
        error = fail(at, "a coordinate is not a finite number");
        return false;
    }
    std::string fail(size_t at, const std::string& problem) const {
        return file_ + ": offset " + std::to_string(at) + ": " + problem;
    }
    size_t offset() const { return offset_; }
    void skip(size_t n) { offset_ += n; }

  private:
    std::span<const uint8_t> bytes_;
    const std::string& file_;
    size_t offset_ = 0;
};

}  // namespace

std::vector<uint8_t> encode_scene(const ObscuranceScene& scene) {
    std::vector<uint8_t> out(kMagic, kMagic + 8);
    out.reserve(kHeaderSize + scene.triangles.size() * kTriangleSize);
    put_u32(out, scene.width);
    put_u32(out, scene.height);
    for (float f : scene.projection) put_f32(out, f);
    put_u32(out, uint32_t(scene.triangles.size()));
    for (const SceneTriangle& t : scene.triangles) {
        put_vec3(out, t.a);
        put_vec3(out, t.b);
        put_vec3(out, t.c);
        put_u32(out, t.solid ? kSolid : 0u);
    }
    return out;
}

SceneParse parse_scene(std::span<const uint8_t> bytes, const std::string& file) {
    SceneParse result;
    Reader in(bytes, file);
    if (bytes.size() < kHeaderSize) {
        result.error = in.fail(bytes.size(), "the file ends inside its " +
                                                 std::to_string(kHeaderSize) + "-byte header");
        return result;
    }
    if (std::memcmp(bytes.data(), kMagic, 8) != 0) {
        result.error = in.fail(0, "not an obscurance scene (no \"NQVOSCN1\" magic)");
        return result;
    }
    in.skip(8);
    ObscuranceScene scene;
    scene.width = in.u32();
    scene.height = in.u32();
    if (scene.width == 0 || scene.height == 0 || scene.width > kMaxSceneSide ||
        scene.height > kMaxSceneSide) {
        result.error = in.fail(8, "viewport " + std::to_string(scene.width) + "x" +
                                      std::to_string(scene.height) + " is not within 1.." +
                                      std::to_string(kMaxSceneSide));
        return result;
    }
    for (float& f : scene.projection) {
        if (!in.f32(f, result.error)) return result;
    }
    const size_t count_at = in.offset();
    const uint32_t count = in.u32();
    const size_t available = (bytes.size() - kHeaderSize) / kTriangleSize;
    if (count != available || bytes.size() != kHeaderSize + size_t(count) * kTriangleSize) {
        result.error =
            in.fail(count_at, "the header counts " + std::to_string(count) +
                                  " triangles but the file holds " +
                                  std::to_string(bytes.size() - kHeaderSize) + " bytes of them (" +
                                  std::to_string(kTriangleSize) + " each)");
        return result;
    }
    scene.triangles.resize(count);
    for (SceneTriangle& t : scene.triangles) {
        for (glm::vec3* v : {&t.a, &t.b, &t.c}) {
            for (int i = 0; i < 3; ++i) {
                if (!in.f32((*v)[i], result.error)) return result;
            }
        }
        const size_t flags_at = in.offset();
        const uint32_t flags = in.u32();
        if ((flags & ~kSolid) != 0) {
            result.error = in.fail(flags_at, "unknown triangle flags " + std::to_string(flags));
            return result;
        }
        t.solid = (flags & kSolid) != 0;
    }
    result.scene = std::move(scene);
    return result;
}

}  // namespace nq::npr::obscurance
