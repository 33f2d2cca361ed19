#include "app/frame/showroom.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "render/view_transform.h"

namespace nq {

namespace {

constexpr int kTiles = 8;  // the floor is kTiles x kTiles surfaces
constexpr float kTileSize = 2 * Showroom::kFloorHalfSize / kTiles;
constexpr int kLightSamplesPerSide = static_cast<int>(kTileSize) / 16 + 1;
constexpr int kFloorTextureSize = 64;
constexpr int kSkinSize = 16;

// Palette indices chosen so the scene reads the same with Quake's palette and the built-in one:
// row 0 greys, row 3 green, row 4 red, row 12 yellow, row 13 blue (bright end of each ramp).
constexpr uint8_t kFloorDark = 6, kFloorLight = 11;
constexpr uint8_t kModelColours[] = {4 * 16 + 5, 13 * 16 + 5, 3 * 16 + 6, 12 * 16 + 5};

float radians(float degrees) {
    return degrees * std::numbers::pi_v<float> / 180.0f;
}

}  // namespace

struct Showroom::FloorStorage {
    std::vector<nqr_surface> surfaces;
    std::vector<float> positions;
    std::vector<uint32_t> vertex_ids;
    std::array<std::vector<uint8_t>, 4> mips;
    nqr_texture texture{};
    std::vector<uint8_t> lighting_rgb;
    nqr_brush_model brush{};
    nqr_model model{};
};

struct Showroom::AliasStorage {
    showroom::Mesh mesh;
    std::vector<int32_t> st;
    std::vector<int32_t> triangles;
    std::vector<nqr_alias_vertex> pose;
    std::vector<uint8_t> skin_pixels;
    const uint8_t* skin_image = nullptr;
    float interval = 0.1f;
    nqr_alias_frame frame{};
    nqr_alias_skin skin{};
    nqr_alias_model alias{};
    nqr_model model{};
    float lift = 0;  // raises the mesh so it stands on the floor
};

namespace {

void build_floor_texture(std::array<std::vector<uint8_t>, 4>& mips) {
    for (int level = 0; level < 4; ++level) {
        int size = kFloorTextureSize >> level;
        int half = size / 2;
        mips[level].resize(size * size);
        for (int y = 0; y < size; ++y) {
            for (int x = 0; x < size; ++x) {
                mips[level][y * size + x] = ((x < half) == (y < half)) ? kFloorLight : kFloorDark;
            }
        }
    }
}

// A grey lightmap value for a floor point: bright under the light, fading with distance.
uint8_t floor_light(float x, float y) {
    float d = std::sqrt(x * x + y * y + Showroom::kLightHeight * Showroom::kLightHeight);
    float v = 70.0f + 185.0f * std::clamp(1.0f - (d - Showroom::kLightHeight) / 700.0f, 0.0f, 1.0f);
    return static_cast<uint8_t>(v);
}

}  // namespace

Showroom::Showroom() : floor_(std::make_unique<FloorStorage>()) {
    FloorStorage& f = *floor_;
    build_floor_texture(f.mips);
    f.texture = nqr_texture{};
    f.texture.size = sizeof(nqr_texture);
    f.texture.name = "showroom_floor";
    f.texture.width = f.texture.height = kFloorTextureSize;
    for (int i = 0; i < 4; ++i) f.texture.mips[i] = f.mips[i].data();

    const float h = kFloorHalfSize;
    const int samples = kLightSamplesPerSide * kLightSamplesPerSide;
    for (int ty = 0; ty < kTiles; ++ty) {
        for (int tx = 0; tx < kTiles; ++tx) {
            float x0 = -h + tx * kTileSize, y0 = -h + ty * kTileSize;
            float x1 = x0 + kTileSize, y1 = y0 + kTileSize;
            nqr_surface s{};
            s.size = sizeof(nqr_surface);
            s.first_vertex = static_cast<uint32_t>(f.positions.size() / 3);
            s.num_vertices = 4;
            // The ABI's winding: counter-clockwise seen from the front (from above).
            const float corners[4][2] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
            const int grid[4][2] = {{tx, ty}, {tx + 1, ty}, {tx + 1, ty + 1}, {tx, ty + 1}};
            for (int c = 0; c < 4; ++c) {
                f.positions.insert(f.positions.end(), {corners[c][0], corners[c][1], 0.0f});
                f.vertex_ids.push_back(grid[c][1] * (kTiles + 1) + grid[c][0]);
            }
            s.normal[2] = 1.0f;
            s.tex_s[0] = 1.0f;
            s.tex_t[1] = 1.0f;
            s.texture = 0;
            s.styles[0] = 0;
            s.styles[1] = s.styles[2] = s.styles[3] = 255;
            s.light_offset = static_cast<int32_t>(f.surfaces.size()) * samples;
            s.texture_mins[0] = static_cast<int32_t>(x0);
            s.texture_mins[1] = static_cast<int32_t>(y0);
            s.extents[0] = s.extents[1] = static_cast<int32_t>(kTileSize);
            for (int j = 0; j < kLightSamplesPerSide; ++j) {
                for (int i = 0; i < kLightSamplesPerSide; ++i) {
                    uint8_t v = floor_light(x0 + i * 16.0f, y0 + j * 16.0f);
                    f.lighting_rgb.insert(f.lighting_rgb.end(), {v, v, v});
                }
            }
            f.surfaces.push_back(s);
        }
    }
    f.brush = nqr_brush_model{};
    f.brush.size = sizeof(nqr_brush_model);
    f.brush.num_surfaces = static_cast<uint32_t>(f.surfaces.size());
    f.brush.surfaces = f.surfaces.data();
    f.brush.num_vertices = static_cast<uint32_t>(f.vertex_ids.size());
    f.brush.positions = f.positions.data();
    f.brush.vertex_ids = f.vertex_ids.data();
    f.brush.num_textures = 1;
    f.brush.textures = &f.texture;
    f.brush.lighting_rgb = f.lighting_rgb.data();
    f.brush.num_light_samples = f.lighting_rgb.size() / 3;
    f.model = nqr_model{};
    f.model.size = sizeof(nqr_model);
    f.model.kind = NQR_MODEL_BRUSH;
    f.model.name = "showroom_floor";
    f.model.mins[0] = f.model.mins[1] = -h;
    f.model.maxs[0] = f.model.maxs[1] = h;
    f.model.radius = h * std::numbers::sqrt2_v<float>;
    f.model.brush = &f.brush;
    f.model.num_surfaces = f.brush.num_surfaces;

    const showroom::Mesh meshes[] = {
        showroom::make_cube(kModelSize), showroom::make_step(kModelSize),
        showroom::make_sphere(kModelSize / 2, 12, 24),
        showroom::make_torus(kModelSize * 0.4f, kModelSize * 0.15f, 24, 12)};
    for (size_t i = 0; i < std::size(meshes); ++i) {
        auto a = std::make_unique<AliasStorage>();
        a->mesh = meshes[i];
        std::array<float, 3> lo{1e9f, 1e9f, 1e9f}, hi{-1e9f, -1e9f, -1e9f};
        for (const auto& p : a->mesh.positions) {
            for (int k = 0; k < 3; ++k) {
                lo[k] = std::min(lo[k], p[k]);
                hi[k] = std::max(hi[k], p[k]);
            }
        }
        nqr_alias_model& m = a->alias;
        m.size = sizeof(nqr_alias_model);
        for (int k = 0; k < 3; ++k) {
            m.origin[k] = lo[k];
            m.scale[k] = std::max(hi[k] - lo[k], 1e-3f) / 255.0f;
        }
        for (const auto& p : a->mesh.positions) {
            nqr_alias_vertex v{};
            for (int k = 0; k < 3; ++k) {
                v.v[k] = static_cast<uint8_t>(std::lround((p[k] - m.origin[k]) / m.scale[k]));
            }
            v.normal_index = 5;  // nprlib derives normals from the triangles
            a->pose.push_back(v);
            a->st.insert(a->st.end(), {0, kSkinSize / 2, kSkinSize / 2});
        }
        // Quake's alias triangles are clockwise seen from outside: swap two corners.
        for (const auto& t : a->mesh.triangles)
            a->triangles.insert(a->triangles.end(), {1, t[0], t[2], t[1]});
        a->skin_pixels.assign(kSkinSize * kSkinSize, kModelColours[i]);
        a->skin_image = a->skin_pixels.data();
        a->frame = nqr_alias_frame{sizeof(nqr_alias_frame), "base", 0, 1, &a->interval};
        a->skin = nqr_alias_skin{sizeof(nqr_alias_skin), 1, &a->skin_image, &a->interval};
        m.skin_width = m.skin_height = kSkinSize;
        m.num_vertices = static_cast<uint32_t>(a->mesh.positions.size());
        m.num_triangles = static_cast<uint32_t>(a->mesh.triangles.size());
        m.num_poses = m.num_frames = m.num_skins = 1;
        m.st = a->st.data();
        m.triangles = a->triangles.data();
        m.poses = a->pose.data();
        m.frames = &a->frame;
        m.skins = &a->skin;
        a->lift = -lo[2];
        nqr_model& model = a->model;
        model.size = sizeof(nqr_model);
        model.kind = NQR_MODEL_ALIAS;
        model.name = a->mesh.name.c_str();
        float radius = 0;
        for (int k = 0; k < 3; ++k) {
            model.mins[k] = lo[k];
            model.maxs[k] = hi[k];
            radius = std::max({radius, std::abs(lo[k]), std::abs(hi[k])});
        }
        model.radius = radius * std::numbers::sqrt3_v<float>;
        model.alias = &a->alias;
        alias_.push_back(std::move(a));
    }
}

Showroom::~Showroom() = default;

void Showroom::assign_ids(nqr_model_id first_id) {
    floor_->model.id = first_id;
    for (size_t i = 0; i < alias_.size(); ++i) {
        alias_[i]->model.id = first_id + 1 + static_cast<nqr_model_id>(i);
    }
}

std::vector<const nqr_model*> Showroom::models() const {
    std::vector<const nqr_model*> out{&floor_->model};
    for (const auto& a : alias_) out.push_back(&a->model);
    return out;
}

std::array<uint8_t, 768> Showroom::builtin_palette() {
    // 14 hue ramps dark -> bright (row 0 grey), then two rows of bright colours (224-255 are
    // fullbright in Quake's convention).
    static const float kHues[16] = {0,   30,  200, 120, 0,  25,  45, 15,
                                    280, 320, 35,  100, 55, 220, 20, 60};
    std::array<uint8_t, 768> pal{};
    for (int row = 0; row < 16; ++row) {
        for (int i = 0; i < 16; ++i) {
            float v = (i + 1) / 16.0f;
            float sat = row == 0 ? 0.0f : 0.75f;
            float h = kHues[row] / 60.0f;
            float c = v * sat, x = c * (1 - std::abs(std::fmod(h, 2.0f) - 1)), m = v - c;
            float r = 0, g = 0, b = 0;
            int sector = static_cast<int>(h) % 6;
            const float rgb[6][3] = {{c, x, 0}, {x, c, 0}, {0, c, x},
                                     {0, x, c}, {x, 0, c}, {c, 0, x}};
            r = rgb[sector][0], g = rgb[sector][1], b = rgb[sector][2];
            int idx = (row * 16 + i) * 3;
            pal[idx] = static_cast<uint8_t>((r + m) * 255);
            pal[idx + 1] = static_cast<uint8_t>((g + m) * 255);
            pal[idx + 2] = static_cast<uint8_t>((b + m) * 255);
        }
    }
    pal[0] = pal[1] = pal[2] = 0;
    return pal;
}

CameraSetup Showroom::default_camera(int width, int height) {
    CameraSetup cam;
    const std::array<float, 3> eye{-260.0f, -200.0f, 170.0f}, target{0.0f, 0.0f, 24.0f};
    float dx = target[0] - eye[0], dy = target[1] - eye[1], dz = target[2] - eye[2];
    cam.origin = {eye[0], eye[1], eye[2]};
    // Quake angles: positive pitch looks down.
    cam.angles = {-std::atan2(dz, std::hypot(dx, dy)) * 180.0f / std::numbers::pi_v<float>,
                  std::atan2(dy, dx) * 180.0f / std::numbers::pi_v<float>, 0.0f};
    cam.viewport[2] = width;
    cam.viewport[3] = height;
    return cam;
}

std::array<float, 3> Showroom::model_origin(size_t i) const {
    float a = radians(90.0f * static_cast<float>(i) + 45.0f);
    return {kOrbitRadius * std::cos(a), kOrbitRadius * std::sin(a), alias_[i]->lift};
}

float Showroom::model_yaw(double time) const {
    return static_cast<float>(std::fmod(time * kTurnDegreesPerSecond, 360.0));
}

void Showroom::fill_light(const std::array<float, 3>& at, EntityLighting& out) const {
    auto light = light_position();
    float d[3] = {light[0] - at[0], light[1] - at[1], light[2] - at[2]};
    float len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    out.ambient = 0.35f;
    out.directional = 0.9f;
    for (int k = 0; k < 3; ++k) {
        out.direction[k] = d[k] / len;
        out.color[k] = 1.0f;
    }
    // The cube holds the even light around, the one lamp is the light list.
    for (auto& face : out.ambient_cube) face[0] = face[1] = face[2] = out.ambient;
    out.num_lights = 1;
    for (nqr_light_source& source : out.sources) {
        source = nqr_light_source{};
        source.size = sizeof(nqr_light_source);
    }
    for (int k = 0; k < 3; ++k) {
        out.sources[0].position[k] = light[k];
        out.sources[0].color[k] = out.directional;
    }
}

const nqr_frame& Showroom::build(SceneBuilder& scene, const CameraSetup& camera, double time,
                                 double real_time, float frame_time) const {
    nqr_frame& frame = scene.begin_custom(camera, time, real_time, frame_time);
    nqr_entity& floor = scene.add_custom_entity(NQR_MODEL_BRUSH);
    floor.model = floor_->model.id;
    floor.number = 1;
    floor.alpha = 1;
    floor.scale = 1;
    fill_entity_transform(NQR_MODEL_BRUSH, *frame.camera, floor);
    fill_light({0, 0, 0}, scene.lighting(floor));
    for (size_t i = 0; i < alias_.size(); ++i) {
        nqr_entity& e = scene.add_custom_entity(NQR_MODEL_ALIAS);
        e.model = alias_[i]->model.id;
        e.number = 2 + static_cast<uint32_t>(i);
        auto o = model_origin(i);
        std::copy(o.begin(), o.end(), e.origin);
        e.angles[1] = model_yaw(time);
        e.scale = 1;
        e.alpha = 1;
        fill_entity_transform(NQR_MODEL_ALIAS, *frame.camera, e);
        fill_light(o, scene.lighting(e));
    }
    return scene.finish_custom();
}

namespace {

bool over_floor(float x, float y) {
    return std::abs(x) <= Showroom::kFloorHalfSize && std::abs(y) <= Showroom::kFloorHalfSize;
}

}  // namespace

void Showroom::trace(const float start[3], const float end[3], nqr_trace* out) {
    out->fraction = 1.0f;
    std::copy(end, end + 3, out->end);
    out->start_solid = start[2] < 0.0f && over_floor(start[0], start[1]) ? 1 : 0;
    if (out->start_solid || start[2] < 0.0f || end[2] >= 0.0f) return;
    const float t = start[2] / (start[2] - end[2]);
    const float x = start[0] + t * (end[0] - start[0]), y = start[1] + t * (end[1] - start[1]);
    if (!over_floor(x, y)) return;
    out->fraction = t;
    out->end[0] = x;
    out->end[1] = y;
    out->end[2] = 0.0f;
    out->plane_normal[0] = out->plane_normal[1] = 0.0f;
    out->plane_normal[2] = 1.0f;
    out->plane_dist = 0.0f;
}

}  // namespace nq
