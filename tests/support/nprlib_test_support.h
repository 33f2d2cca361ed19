// Shared by the nprlib_*_test.cpp files: a hidden window with an OpenGL 3.3+ core context on
// SDL's offscreen driver (Mesa llvmpipe, no display needed) rendering into a 128x128 RGBA8 +
// depth framebuffer, a synthetic palette with known colours, a Quake camera built with glm, and
// builders that assemble the ABI structs (nqr_model & co.) by hand, keeping their storage alive.
#pragma once

#include <SDL.h>
#include <dlfcn.h>
#include <epoxy/gl.h>
#include <gtest/gtest.h>
#include <link.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "nqr_renderer.h"
#include "video/resident_libraries.h"
#include "support/video_test_support.h"

namespace nq::npr::test {

inline constexpr int kSize = 128;  // framebuffer width and height

// ------------------------------------------------------------------ GL context + framebuffer

using nq::keep_loaded_libraries_resident;  // see video/resident_libraries.h

struct Rgb {
    int r = 0, g = 0, b = 0;
    bool operator==(const Rgb&) const = default;
};

inline std::ostream& operator<<(std::ostream& out, const Rgb& c) {
    return out << "(" << c.r << ", " << c.g << ", " << c.b << ")";
}

inline bool near(const Rgb& a, const Rgb& b, int tolerance) {
    return std::abs(a.r - b.r) <= tolerance && std::abs(a.g - b.g) <= tolerance &&
           std::abs(a.b - b.b) <= tolerance;
}

inline int brightness(const Rgb& c) {
    return c.r + c.g + c.b;
}

class GlTestContext {
  public:
    // Creates window, context (the engine's VideoWindow, as the video tests make it) and
    // framebuffer; error() says why when it could not.
    GlTestContext() {
        auto created = nq::test::make_offscreen_window(kSize, kSize);
        if (!created) {
            error_ = created.error().message;
            return;
        }
        window_.emplace(std::move(*created));
        create_framebuffer();
    }

    ~GlTestContext() {
        if (window_) {
            glDeleteFramebuffers(1, &framebuffer_);
            glDeleteTextures(1, &colour_);
            glDeleteRenderbuffers(1, &depth_);
        }
    }

    const std::string& error() const { return error_; }
    bool ok() const { return error_.empty(); }

    void bind() const {
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
        glViewport(0, 0, kSize, kSize);
    }

    void clear(Rgb colour = {}) const {
        bind();
        glClearColor(colour.r / 255.0f, colour.g / 255.0f, colour.b / 255.0f, 1.0f);
        glDepthMask(GL_TRUE);
        glClearDepth(1.0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    }

    // x, y in GL window coordinates (origin bottom-left).
    Rgb pixel(int x, int y) const {
        uint8_t rgba[4] = {};
        glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
        return {rgba[0], rgba[1], rgba[2]};
    }

    std::vector<Rgb> pixels() const {
        std::vector<uint8_t> rgba(kSize * kSize * 4);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
        std::vector<Rgb> out(kSize * kSize);
        for (int i = 0; i < kSize * kSize; ++i)
            out[i] = {rgba[i * 4], rgba[i * 4 + 1], rgba[i * 4 + 2]};
        return out;
    }

    GLuint framebuffer() const { return framebuffer_; }

    // Debugging aid: with NQ_TEST_DUMP_DIR set, writes the framebuffer as <dir>/<name>.ppm.
    void dump_if_requested(const std::string& name) const {
        const char* dir = std::getenv("NQ_TEST_DUMP_DIR");
        if (!dir) return;
        const std::vector<Rgb> image = pixels();
        std::string out = "P6\n" + std::to_string(kSize) + " " + std::to_string(kSize) + "\n255\n";
        for (int y = kSize - 1; y >= 0; --y) {
            for (int x = 0; x < kSize; ++x) {
                const Rgb& p = image[y * kSize + x];
                out += {static_cast<char>(p.r), static_cast<char>(p.g), static_cast<char>(p.b)};
            }
        }
        if (FILE* file = std::fopen((std::string(dir) + "/" + name + ".ppm").c_str(), "wb")) {
            std::fwrite(out.data(), 1, out.size(), file);
            std::fclose(file);
        }
    }

  private:
    void create_framebuffer() {
        glGenTextures(1, &colour_);
        glBindTexture(GL_TEXTURE_2D, colour_);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, kSize, kSize, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                     nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glBindTexture(GL_TEXTURE_2D, 0);
        glGenRenderbuffers(1, &depth_);
        glBindRenderbuffer(GL_RENDERBUFFER, depth_);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, kSize, kSize);
        glGenFramebuffers(1, &framebuffer_);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour_, 0);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                                  depth_);
        if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
            error_ = "test framebuffer incomplete";
        }
    }

    std::string error_;
    std::optional<VideoWindow> window_;
    GLuint framebuffer_ = 0, colour_ = 0, depth_ = 0;
};

// An RGBA8 + 24-bit depth framebuffer of any size, bound (with its viewport) on creation.
class SizedFramebuffer {
  public:
    SizedFramebuffer(int width, int height) : width_(width), height_(height) {
        glGenFramebuffers(1, &framebuffer_);
        glGenRenderbuffers(2, renderbuffers_);
        glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[0]);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
        glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[1]);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
        bind();
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                  renderbuffers_[0]);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                  renderbuffers_[1]);
    }
    ~SizedFramebuffer() {
        glDeleteFramebuffers(1, &framebuffer_);
        glDeleteRenderbuffers(2, renderbuffers_);
    }
    SizedFramebuffer(const SizedFramebuffer&) = delete;
    SizedFramebuffer& operator=(const SizedFramebuffer&) = delete;

    void bind() const {
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
        glViewport(0, 0, width_, height_);
    }
    bool complete() const {
        bind();
        return glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    }

  private:
    int width_, height_;
    GLuint framebuffer_ = 0;
    GLuint renderbuffers_[2] = {};
};

// A fixture base with one GL context per test suite (contexts are slow to make under ASan),
// checked and bound before every test: class MyTest : public GlSuiteTest<MyTest> { ... }.
// A derived SetUp() calls GlSuiteTest::SetUp() first and returns on HasFatalFailure().
template <class Suite>
class GlSuiteTest : public ::testing::Test {
  protected:
    static void SetUpTestSuite() { gl_ = new GlTestContext(); }
    static void TearDownTestSuite() {
        delete gl_;
        gl_ = nullptr;
    }
    void SetUp() override {
        ASSERT_TRUE(gl_->ok()) << gl_->error();
        gl_->bind();
    }

    static inline GlTestContext* gl_ = nullptr;
};

// ------------------------------------------------------------------ palette

// Greyscale (i, i, i) except the entries the tests look for:
namespace colour {
inline constexpr uint8_t kSkyTransparent = 0;  // the sky front layer's "see through" index
inline constexpr uint8_t kShirtBase = 16;      // 16..31: green ramp (skin pixels to translate)
inline constexpr uint8_t kRed = 40;            // (120, 30, 20)
inline constexpr uint8_t kBlue = 41;           // (20, 40, 110)
inline constexpr uint8_t kOrange = 42;         // (90, 60, 20)
inline constexpr uint8_t kTeal = 43;           // (20, 90, 80)
inline constexpr uint8_t kRedRow = 64;         // 64..79: red ramp (player colour 4)
inline constexpr uint8_t kPantsBase = 96;      // 96..111: blue ramp
inline constexpr uint8_t kYellowRow = 192;     // 192..207: yellow ramp, bright to dark (colour 12)
inline constexpr uint8_t kFullbrightGreen = 240;  // (0, 250, 0), a fullbright index
inline constexpr uint8_t kTransparent = 255;      // (255, 0, 255): must never be seen
}  // namespace colour

inline std::array<uint8_t, 768> make_test_palette() {
    std::array<uint8_t, 768> p{};
    auto set = [&](int i, int r, int g, int b) {
        p[i * 3] = static_cast<uint8_t>(r);
        p[i * 3 + 1] = static_cast<uint8_t>(g);
        p[i * 3 + 2] = static_cast<uint8_t>(b);
    };
    for (int i = 0; i < 256; ++i) set(i, i, i, i);
    for (int k = 0; k < 16; ++k) {
        set(colour::kShirtBase + k, 0, 40 + k * 10, 0);
        set(colour::kRedRow + k, 40 + k * 12, 0, 0);
        set(colour::kPantsBase + k, 0, 0, 40 + k * 10);
        set(colour::kYellowRow + k, 240 - k * 12, 240 - k * 12, 0);
    }
    set(colour::kRed, 120, 30, 20);
    set(colour::kBlue, 20, 40, 110);
    set(colour::kOrange, 90, 60, 20);
    set(colour::kTeal, 20, 90, 80);
    set(colour::kFullbrightGreen, 0, 250, 0);
    set(colour::kTransparent, 255, 0, 255);
    return p;
}

inline Rgb palette_colour(const std::array<uint8_t, 768>& p, int index) {
    return {p[index * 3], p[index * 3 + 1], p[index * 3 + 2]};
}

// ------------------------------------------------------------------ engine services

inline std::vector<std::string>& captured_log() {
    static std::vector<std::string> lines;  // test-side only: the log hook is a C function
    return lines;
}

struct TestEngine {
    std::array<uint8_t, 768> palette = make_test_palette();
    std::array<uint8_t, 64 * 256 + 256> colormap{};
    nqr_engine engine{};

    TestEngine() {
        engine.size = sizeof(nqr_engine);
        engine.abi_version = NQR_ABI_VERSION;
        engine.log = [](void*, int, const char* text) { captured_log().push_back(text); };
        engine.palette = palette.data();
        engine.colormap = colormap.data();
    }
};

// ------------------------------------------------------------------ camera

// A camera at `eye` looking along Quake angles (pitch, yaw, roll in degrees: positive pitch
// looks down), perspective with vertical field of view `fov_y`.
inline nqr_camera make_camera(glm::vec3 eye, glm::vec3 angles, float fov_y = 90.0f,
                              float z_near = 1.0f, float z_far = 4096.0f) {
    const float pitch = glm::radians(angles.x), yaw = glm::radians(angles.y),
                roll = glm::radians(angles.z);
    const float sp = std::sin(pitch), cp = std::cos(pitch), sy = std::sin(yaw), cy = std::cos(yaw),
                sr = std::sin(roll), cr = std::cos(roll);
    const glm::vec3 forward(cp * cy, cp * sy, -sp);
    const glm::vec3 right(-sr * sp * cy + cr * sy, -sr * sp * sy - cr * cy, -sr * cp);
    const glm::vec3 up(cr * sp * cy + sr * sy, cr * sp * sy - sr * cy, cr * cp);
    // glm::lookAt maps forward to -Z, up to +Y and forward x up (= Quake's right) to +X: the
    // Quake -> GL axis change the ABI's view matrix contains.
    const glm::mat4 view = glm::lookAt(eye, eye + forward, up);
    const glm::mat4 projection = glm::perspective(glm::radians(fov_y), 1.0f, z_near, z_far);
    const glm::mat4 view_projection = projection * view;

    nqr_camera camera{};
    camera.size = sizeof(nqr_camera);
    std::copy_n(glm::value_ptr(eye), 3, camera.origin);
    std::copy_n(glm::value_ptr(angles), 3, camera.angles);
    std::copy_n(glm::value_ptr(forward), 3, camera.forward);
    std::copy_n(glm::value_ptr(right), 3, camera.right);
    std::copy_n(glm::value_ptr(up), 3, camera.up);
    std::copy_n(glm::value_ptr(view), 16, camera.view);
    std::copy_n(glm::value_ptr(projection), 16, camera.projection);
    std::copy_n(glm::value_ptr(view_projection), 16, camera.view_projection);
    camera.fov_x = camera.fov_y = fov_y;
    camera.z_near = z_near;
    camera.z_far = z_far;
    camera.viewport[2] = camera.viewport[3] = kSize;
    return camera;
}

// Window pixel (x, y) where a world point lands with this camera.
inline glm::vec2 project(const nqr_camera& camera, glm::vec3 world) {
    const glm::vec4 clip = glm::make_mat4(camera.view_projection) * glm::vec4(world, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return (ndc * 0.5f + 0.5f) * static_cast<float>(kSize);
}

// ------------------------------------------------------------------ frames

struct TestFrame {
    std::array<float, 64> lightstyles{};
    std::vector<const nqr_entity*> brush, alias, sprite;
    std::vector<nqr_dlight> dlights;
    std::vector<nqr_particle> particles;
    std::vector<uint32_t> visible;
    bool use_visible_list = false;
    nqr_frame frame{};
    nqr_camera camera{};  // frame.camera points here

    TestFrame() { lightstyles.fill(1.0f); }

    const nqr_frame* build(const nqr_camera& camera, nqr_model_id world, double time = 0.0) {
        frame = nqr_frame{};
        frame.size = sizeof(nqr_frame);
        frame.number = ++number_;
        frame.time = time;
        this->camera = camera;
        frame.camera = &this->camera;
        frame.world = world;
        frame.visible_surfaces = use_visible_list ? visible.data() : nullptr;
        frame.num_visible_surfaces = static_cast<uint32_t>(visible.size());
        frame.lightstyles = lightstyles.data();
        frame.brush_entities = brush.data();
        frame.num_brush_entities = static_cast<uint32_t>(brush.size());
        frame.alias_entities = alias.data();
        frame.num_alias_entities = static_cast<uint32_t>(alias.size());
        frame.sprite_entities = sprite.data();
        frame.num_sprite_entities = static_cast<uint32_t>(sprite.size());
        frame.dlights = dlights.empty() ? nullptr : dlights.data();
        frame.num_dlights = static_cast<uint32_t>(dlights.size());
        frame.particles = particles.empty() ? nullptr : particles.data();
        frame.num_particles = static_cast<uint32_t>(particles.size());
        return &frame;
    }

  private:
    uint64_t number_ = 0;
};

inline nqr_dlight make_dlight(glm::vec3 origin, float radius, glm::vec3 colour = glm::vec3(1)) {
    nqr_dlight light{};
    light.size = sizeof(nqr_dlight);
    std::copy_n(glm::value_ptr(origin), 3, light.origin);
    light.radius = radius;
    std::copy_n(glm::value_ptr(colour), 3, light.color);
    return light;
}

inline nqr_particle make_particle(glm::vec3 origin, uint8_t colour_index, float alpha = 1.0f) {
    nqr_particle particle{};
    particle.size = sizeof(nqr_particle);
    std::copy_n(glm::value_ptr(origin), 3, particle.origin);
    particle.color = colour_index;
    particle.alpha = alpha;
    return particle;
}

// Normal white light from straight above, no light list: what make_entity's entities point to.
// A test that changes an entity's light points it at a make_light() of its own.
inline nqr_entity_light make_light() {
    nqr_entity_light light{};
    light.size = sizeof(nqr_entity_light);
    light.ambient = 1.0f;
    light.direction[2] = 1.0f;
    light.color[0] = light.color[1] = light.color[2] = 1.0f;
    return light;
}
inline const nqr_entity_light& default_light() {
    static const nqr_entity_light light = make_light();
    return light;
}

// An entity's light with room for its light list, for tests that set one.
struct TestLight {
    nqr_entity_light light = make_light();
    std::array<nqr_light_source, NQR_MAX_ENTITY_LIGHTS> sources{};
    TestLight() {
        light.lights = sources.data();
        for (nqr_light_source& s : sources) s.size = sizeof(nqr_light_source);
    }
    TestLight(const TestLight&) = delete;
    TestLight& operator=(const TestLight&) = delete;
};

inline nqr_entity make_entity(nqr_model_id model, glm::mat4 model_matrix = glm::mat4(1.0f)) {
    nqr_entity entity{};
    entity.size = sizeof(nqr_entity);
    entity.model = model;
    entity.scale = 1.0f;
    entity.alpha = 1.0f;
    std::copy_n(glm::value_ptr(model_matrix), 16, entity.model_matrix);
    const glm::vec3 origin(model_matrix[3]);
    std::copy_n(glm::value_ptr(origin), 3, entity.origin);
    entity.light = &default_light();
    return entity;
}

// ------------------------------------------------------------------ brush models

// A palette image filled by a function of (x, y).
template <class F>
std::vector<uint8_t> make_image(int width, int height, F index_at) {
    std::vector<uint8_t> pixels(static_cast<size_t>(width) * height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) pixels[y * width + x] = index_at(x, y);
    }
    return pixels;
}

// Builds an nqr_brush_model from axis-aligned quads. Texture mapping: texel s = x * s_scale,
// t = y * t_scale for floors (z = const); lightmaps from per-quad sample values.
class BrushBuilder {
  public:
    int add_texture(const std::string& name, int width, int height, std::vector<uint8_t> pixels,
                    uint32_t flags = 0) {
        TextureData data;
        data.name = name;
        data.width = width;
        data.height = height;
        data.pixels = std::move(pixels);
        data.flags = flags;
        textures_.push_back(std::move(data));
        return static_cast<int>(textures_.size() - 1);
    }

    void set_animation(int texture, std::vector<int32_t> frames,
                       std::vector<int32_t> alternate = {}) {
        textures_[texture].anim = std::move(frames);
        textures_[texture].alt_anim = std::move(alternate);
    }

    struct Quad {
        // Floor quad spanning [x0, x1] x [y0, y1] at height z, facing up (+Z).
        float x0, y0, x1, y1, z;
        int texture;
        float texels_per_unit = 1.0f;  // s = x * this, t = y * this
        uint32_t flags = 0;
        std::array<uint8_t, 4> styles = {0, 255, 255, 255};
        // One light value per style (grey), or a function of the sample (s, t) when set.
        std::array<uint8_t, 4> light = {128, 0, 0, 0};
        bool no_samples = false;
    };

    // Returns the surface index.
    uint32_t add_floor(const Quad& quad) {
        quads_.push_back(quad);
        return static_cast<uint32_t>(quads_.size() - 1);
    }

    // Fills the nqr structs; call once after every add_*.
    const nqr_brush_model* build(bool with_lighting = true) {
        positions_.clear();
        surfaces_.clear();
        lighting_.clear();
        vertex_ids_.clear();
        for (const Quad& quad : quads_) add_surface(quad);
        nqr_textures_.clear();
        for (const TextureData& data : textures_) nqr_textures_.push_back(to_nqr(data));
        brush_ = nqr_brush_model{};
        brush_.size = sizeof(nqr_brush_model);
        brush_.num_surfaces = static_cast<uint32_t>(surfaces_.size());
        brush_.surfaces = surfaces_.data();
        brush_.num_vertices = static_cast<uint32_t>(positions_.size() / 3);
        brush_.positions = positions_.data();
        brush_.vertex_ids = vertex_ids_.data();
        brush_.num_textures = static_cast<uint32_t>(nqr_textures_.size());
        brush_.textures = nqr_textures_.data();
        brush_.lighting_rgb = with_lighting ? lighting_.data() : nullptr;
        brush_.num_light_samples = with_lighting ? lighting_.size() / 3 : 0;
        return &brush_;
    }

    // An nqr_model covering [first, first + count) of the built brush model.
    nqr_model model(nqr_model_id id, uint32_t first, uint32_t count, const char* name = "*0") {
        nqr_model m{};
        m.size = sizeof(nqr_model);
        m.id = id;
        m.kind = NQR_MODEL_BRUSH;
        m.name = name;
        m.brush = &brush_;
        m.first_surface = first;
        m.num_surfaces = count;
        return m;
    }

    std::vector<nqr_surface>& surfaces() { return surfaces_; }

  private:
    struct TextureData {
        std::string name;
        int width = 0, height = 0;
        std::vector<uint8_t> pixels;
        uint32_t flags = 0;
        std::vector<int32_t> anim, alt_anim;
    };

    nqr_texture to_nqr(const TextureData& data) const {
        nqr_texture t{};
        t.size = sizeof(nqr_texture);
        t.name = data.name.c_str();
        t.width = static_cast<uint32_t>(data.width);
        t.height = static_cast<uint32_t>(data.height);
        t.mips[0] = data.pixels.data();
        t.flags = data.flags;
        t.num_anim_frames = static_cast<uint32_t>(data.anim.size());
        t.num_alt_anim_frames = static_cast<uint32_t>(data.alt_anim.size());
        for (size_t i = 0; i < data.anim.size(); ++i) t.anim_frames[i] = data.anim[i];
        for (size_t i = 0; i < data.alt_anim.size(); ++i) t.alt_anim_frames[i] = data.alt_anim[i];
        return t;
    }

    void add_surface(const Quad& quad) {
        nqr_surface s{};
        s.size = sizeof(nqr_surface);
        s.first_vertex = static_cast<uint32_t>(positions_.size() / 3);
        s.num_vertices = 4;
        // Counter-clockwise seen from above (the front), as the ABI hands polygons over.
        const float corners[4][2] = {
            {quad.x0, quad.y0}, {quad.x1, quad.y0}, {quad.x1, quad.y1}, {quad.x0, quad.y1}};
        for (const auto& c : corners) {
            positions_.insert(positions_.end(), {c[0], c[1], quad.z});
            vertex_ids_.push_back(static_cast<uint32_t>(vertex_ids_.size()));
        }
        s.normal[2] = 1.0f;
        s.dist = quad.z;
        s.tex_s[0] = quad.texels_per_unit;
        s.tex_t[1] = quad.texels_per_unit;
        s.texture = quad.texture;
        s.flags = quad.flags;
        std::copy(quad.styles.begin(), quad.styles.end(), s.styles);
        // Quake: texture_mins = floor(min / 16) * 16, extents = ceil(max / 16) * 16 - mins.
        const float s0 = quad.x0 * quad.texels_per_unit, s1 = quad.x1 * quad.texels_per_unit;
        const float t0 = quad.y0 * quad.texels_per_unit, t1 = quad.y1 * quad.texels_per_unit;
        s.texture_mins[0] = static_cast<int32_t>(std::floor(s0 / 16.0f) * 16);
        s.texture_mins[1] = static_cast<int32_t>(std::floor(t0 / 16.0f) * 16);
        s.extents[0] = static_cast<int32_t>(std::ceil(s1 / 16.0f) * 16) - s.texture_mins[0];
        s.extents[1] = static_cast<int32_t>(std::ceil(t1 / 16.0f) * 16) - s.texture_mins[1];
        s.light_offset = -1;
        const bool lit = !(quad.flags & (NQR_SURFACE_SKY | NQR_SURFACE_LIQUID));
        if (lit && !quad.no_samples) {
            s.light_offset = static_cast<int32_t>(lighting_.size() / 3);
            const int samples = ((s.extents[0] >> 4) + 1) * ((s.extents[1] >> 4) + 1);
            for (int style = 0; style < 4 && quad.styles[style] != 255; ++style) {
                for (int i = 0; i < samples * 3; ++i) lighting_.push_back(quad.light[style]);
            }
        }
        surfaces_.push_back(s);
    }

    std::deque<TextureData> textures_;  // deque: names stay put while more are added
    std::vector<Quad> quads_;
    std::vector<float> positions_;
    std::vector<uint32_t> vertex_ids_;
    std::vector<nqr_surface> surfaces_;
    std::vector<nqr_texture> nqr_textures_;
    std::vector<uint8_t> lighting_;
    nqr_brush_model brush_{};
};

// ------------------------------------------------------------------ alias models

// An alias model from explicit vertices (model-space positions on a 1-unit grid: scale 1,
// origin 0), triangles, poses and a single skin.
class AliasBuilder {
  public:
    int skin_width = 8, skin_height = 8;
    std::vector<uint8_t> skin;  // skin_width x skin_height
    std::vector<std::array<int32_t, 3>> st;
    std::vector<std::array<int32_t, 4>> triangles;  // facesfront, v0, v1, v2
    std::vector<std::vector<std::array<uint8_t, 3>>> poses;
    glm::vec3 scale{1.0f}, origin{0.0f};
    uint32_t flags = 0;

    // A closed box: 8 corners from `lo` to `hi` (packed bytes), 12 triangles wound clockwise
    // seen from outside, as Quake stores them. Adds one pose per call.
    void add_box_pose(glm::ivec3 lo, glm::ivec3 hi) {
        std::vector<std::array<uint8_t, 3>> pose;
        for (int i = 0; i < 8; ++i) {
            pose.push_back({static_cast<uint8_t>(i & 1 ? hi.x : lo.x),
                            static_cast<uint8_t>(i & 2 ? hi.y : lo.y),
                            static_cast<uint8_t>(i & 4 ? hi.z : lo.z)});
        }
        poses.push_back(pose);
        if (triangles.empty()) {
            // Faces as corner quads (counter-clockwise from outside), emitted reversed.
            const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                     {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
            for (const auto& f : faces) {
                triangles.push_back({1, f[0], f[2], f[1]});
                triangles.push_back({1, f[0], f[3], f[2]});
            }
            for (int i = 0; i < 8; ++i) st.push_back({0, 4, 4});
        }
    }

    const nqr_alias_model* build() {
        flat_st_.clear();
        for (const auto& v : st) flat_st_.insert(flat_st_.end(), v.begin(), v.end());
        flat_triangles_.clear();
        for (const auto& t : triangles)
            flat_triangles_.insert(flat_triangles_.end(), t.begin(), t.end());
        flat_poses_.clear();
        for (const auto& pose : poses) {
            for (const auto& v : pose) flat_poses_.push_back({{v[0], v[1], v[2]}, 0});
        }
        skin_pointer_ = skin.data();
        skin_record_ = nqr_alias_skin{};
        skin_record_.size = sizeof(nqr_alias_skin);
        skin_record_.num_images = 1;
        skin_record_.images = &skin_pointer_;
        frames_.clear();
        for (size_t i = 0; i < poses.size(); ++i) {
            nqr_alias_frame frame{};
            frame.size = sizeof(nqr_alias_frame);
            frame.name = "frame";
            frame.first_pose = static_cast<uint32_t>(i);
            frame.num_poses = 1;
            frames_.push_back(frame);
        }
        model_ = nqr_alias_model{};
        model_.size = sizeof(nqr_alias_model);
        std::copy_n(glm::value_ptr(scale), 3, model_.scale);
        std::copy_n(glm::value_ptr(origin), 3, model_.origin);
        model_.skin_width = skin_width;
        model_.skin_height = skin_height;
        model_.num_vertices = static_cast<uint32_t>(st.size());
        model_.num_triangles = static_cast<uint32_t>(triangles.size());
        model_.num_poses = static_cast<uint32_t>(poses.size());
        model_.num_frames = static_cast<uint32_t>(frames_.size());
        model_.num_skins = 1;
        model_.flags = flags;
        model_.st = flat_st_.data();
        model_.triangles = flat_triangles_.data();
        model_.poses = flat_poses_.data();
        model_.frames = frames_.data();
        model_.skins = &skin_record_;
        return &model_;
    }

    nqr_model model(nqr_model_id id) {
        nqr_model m{};
        m.size = sizeof(nqr_model);
        m.id = id;
        m.kind = NQR_MODEL_ALIAS;
        m.name = "progs/test.mdl";
        m.alias = &model_;
        return m;
    }

  private:
    std::vector<int32_t> flat_st_, flat_triangles_;
    std::vector<nqr_alias_vertex> flat_poses_;
    const uint8_t* skin_pointer_ = nullptr;
    nqr_alias_skin skin_record_{};
    std::vector<nqr_alias_frame> frames_;
    nqr_alias_model model_{};
};

// ------------------------------------------------------------------ sprites

class SpriteBuilder {
  public:
    uint32_t type = 2;  // parallel
    struct Image {
        int width, height, origin_x, origin_y;
        std::vector<uint8_t> pixels;
    };
    std::vector<Image> images;

    nqr_model model(nqr_model_id id) {
        records_.clear();
        for (const Image& image : images) {
            nqr_sprite_image r{};
            r.size = sizeof(nqr_sprite_image);
            r.width = image.width;
            r.height = image.height;
            r.origin_x = image.origin_x;
            r.origin_y = image.origin_y;
            r.pixels = image.pixels.data();
            records_.push_back(r);
        }
        frames_.clear();
        for (size_t i = 0; i < images.size(); ++i) {
            nqr_sprite_frame f{};
            f.size = sizeof(nqr_sprite_frame);
            f.first_image = static_cast<uint32_t>(i);
            f.num_images = 1;
            frames_.push_back(f);
        }
        sprite_ = nqr_sprite_model{};
        sprite_.size = sizeof(nqr_sprite_model);
        sprite_.type = type;
        sprite_.num_images = static_cast<uint32_t>(records_.size());
        sprite_.num_frames = static_cast<uint32_t>(frames_.size());
        sprite_.images = records_.data();
        sprite_.frames = frames_.data();
        nqr_model m{};
        m.size = sizeof(nqr_model);
        m.id = id;
        m.kind = NQR_MODEL_SPRITE;
        m.name = "progs/test.spr";
        m.sprite = &sprite_;
        return m;
    }

  private:
    std::vector<nqr_sprite_image> records_;
    std::vector<nqr_sprite_frame> frames_;
    nqr_sprite_model sprite_{};
};

// ------------------------------------------------------------------ pixel statistics

struct Coverage {
    int count = 0;
    glm::vec2 centroid{0.0f};
    int min_x = kSize, max_x = -1, min_y = kSize, max_y = -1;
};

// Pixels that differ from `background` by more than `tolerance`.
inline Coverage coverage(const std::vector<Rgb>& pixels, Rgb background, int tolerance = 8) {
    Coverage c;
    glm::vec2 sum(0.0f);
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            if (near(pixels[y * kSize + x], background, tolerance)) continue;
            ++c.count;
            sum += glm::vec2(x + 0.5f, y + 0.5f);
            c.min_x = std::min(c.min_x, x);
            c.max_x = std::max(c.max_x, x);
            c.min_y = std::min(c.min_y, y);
            c.max_y = std::max(c.max_y, y);
        }
    }
    if (c.count) c.centroid = sum / static_cast<float>(c.count);
    return c;
}

}  // namespace nq::npr::test
