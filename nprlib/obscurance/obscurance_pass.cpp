#include "obscurance/obscurance_pass.h"

#include <epoxy/gl.h>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <vector>

#include "obscurance/obscurance_glsl.h"
#include "obscurance/sample_tables.h"

namespace nq::npr::obscurance {
namespace {

constexpr int kUnitDepth = 0;
constexpr int kUnitNormal = 1;
constexpr int kUnitOpen = 2;
constexpr int kUnitMoments = 3;
constexpr int kUnitColour = 4;
constexpr int kReferenceGrid = 64;  // lines per side of the reference's grid (~3,200 lines)
// area1's mip chain of depth moments: levels 0..7, its size padded to a multiple of the last
// level's texel (128) so that every level averages exact 2 x 2 blocks, as the shader assumes.
constexpr int kMomentsLevels = 8;
constexpr int kMomentsPadding = 1 << (kMomentsLevels - 1);

int padded(int size) {
    return (size + kMomentsPadding - 1) / kMomentsPadding * kMomentsPadding;
}

// Scene uv to the padded moments texture's uv.
void set_moments_scale(gl::Program& program, const SceneTextures& scene) {
    glUniform2f(program.location("u_moments_scale"),
                float(scene.width) / float(padded(scene.width)),
                float(scene.height) / float(padded(scene.height)));
}

std::string estimate_defines(ObscuranceMode mode, int samples) {
    const std::string count =
        std::to_string(mode == ObscuranceMode::reference ? kReferenceGrid : samples);
    if (samples_lines(mode)) return "#define VO_LINES " + count + "\n";
    if (samples_points(mode)) return "#define VO_POINTS " + count + "\n";
    if (mode == ObscuranceMode::area1) {
        return "#define VO_AREA\n#define VO_MOMENTS_LEVELS " + std::to_string(kMomentsLevels) +
               "\n";
    }
    return "#define VO_REFERENCE " + count + "\n";
}

void bind_texture(int unit, GLuint texture) {
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_2D, texture);
}

// GL state the pass changes and gives back.
struct SavedState {
    GLboolean depth_test = glIsEnabled(GL_DEPTH_TEST);
    GLboolean blend = glIsEnabled(GL_BLEND);
    GLboolean cull = glIsEnabled(GL_CULL_FACE);
    GLint viewport[4] = {};
    GLint blend_source = GL_ONE, blend_destination = GL_ZERO;
    SavedState() {
        glGetIntegerv(GL_VIEWPORT, viewport);
        glGetIntegerv(GL_BLEND_SRC_RGB, &blend_source);
        glGetIntegerv(GL_BLEND_DST_RGB, &blend_destination);
    }
    ~SavedState() {
        glBlendFunc(GLenum(blend_source), GLenum(blend_destination));
        if (depth_test) glEnable(GL_DEPTH_TEST);
        if (blend)
            glEnable(GL_BLEND);
        else
            glDisable(GL_BLEND);
        if (cull) glEnable(GL_CULL_FACE);
        glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
    }
};

}  // namespace

void ObscurancePass::reset() {
    stages_ = {};
    moments_program_.reset();
    composite_.reset();
    moments_ = Target{};
    moments_width_ = moments_height_ = 0;
    empty_vertex_array_.reset();
    for (Target& target : targets_) target = Target{};
    result_ = nullptr;
    target_width_ = target_height_ = 0;
    gl_version_ = 0;  // the next context may be another
    compute_refused_ = false;
    clock_.reset();
    trial_.restart();
    trial_key_ = TrialKey{};
    trial_issued_ = trial_read_ = 0;
}

// `source` built into `program`; false with `error` when it does not build.
bool ObscurancePass::build(gl::Program& program, const gl::ProgramSource& source,
                           std::string& error) {
    gl::ProgramBuild build = gl::Program::build(source, tracker_);
    if (!build.ok()) {
        error = build.error;
        return false;
    }
    program = std::move(build.program);
    return true;
}

// A full-screen program from a fragment source, into `program`; false with `error` when it
// does not build.
bool ObscurancePass::build_fullscreen(gl::Program& program, const char* name,
                                      const std::string& fragment, std::string& error) {
    return build(program, {name, kFullscreenVertex, fragment.c_str()}, error);
}

// The estimate or the blur, whose source defines pass_result(pixel): a compute program, or a
// full-screen one.
bool ObscurancePass::build_stage(gl::Program& program, const char* name, const std::string& body,
                                 StagePath path, std::string& error) {
    if (path == StagePath::fragment) {
        return build_fullscreen(program, name, kFragmentHeader + body + kFragmentMain, error);
    }
    const std::string source = kComputeHeader +
                               ("#define VO_GROUP " + std::to_string(kComputeGroupSize) + "\n") +
                               body + kComputeMain;
    gl::ProgramSource stage{name, nullptr, nullptr};
    stage.compute = source.c_str();
    return build(program, stage, error);
}

bool ObscurancePass::build_estimate(ObscuranceMode mode, int samples, StagePath path,
                                    std::string& error) {
    StagePrograms& programs = stages_[size_t(path)];
    gl::Program& estimate = programs.estimate[static_cast<size_t>(mode)];
    if (estimate && programs.uploaded[static_cast<size_t>(mode)].count != samples) {
        estimate.reset();  // another vo_sample_count
    }
    if (estimate) return true;
    const std::string body = estimate_defines(mode, samples) + kSceneLibrary + kEstimate;
    if (!build_stage(estimate, "obscurance estimate", body, path, error)) return false;
    gl::bind_sampler_units(estimate, {"u_depth", "u_normal"});
    estimate.use();
    if (mode == ObscuranceMode::area1) glUniform1i(estimate.location("u_moments"), kUnitMoments);
    upload_samples(programs, mode, {SampleMethod::electrostatic, samples});
    return true;
}

bool ObscurancePass::build_blur(StagePath path, std::string& error) {
    gl::Program& blur = stages_[size_t(path)].blur;
    if (blur) return true;
    if (!build_stage(blur, "obscurance blur", kBlur, path, error)) return false;
    blur.use();
    glUniform1i(blur.location("u_open"), kUnitOpen);
    return true;
}

// What runs the same way on every path: area1's moments, the composite.
bool ObscurancePass::build_shared(ObscuranceMode mode, std::string& error) {
    if (mode == ObscuranceMode::area1 && !moments_program_) {
        if (!build_fullscreen(moments_program_, "obscurance moments",
                              std::string(kFragmentHeader) + kSceneLibrary + kMomentsFragment,
                              error)) {
            return false;
        }
        gl::bind_sampler_units(moments_program_, {"u_depth", "u_normal"});
    }
    if (!composite_) {
        if (!build_fullscreen(composite_, "obscurance composite",
                              std::string(kFragmentHeader) + kSceneLibrary + kCompositeFragment,
                              error)) {
            return false;
        }
        gl::bind_sampler_units(composite_, {"u_depth", "u_normal", "u_open"});
        glUniform1i(composite_.location("u_colour"), kUnitColour);
    }
    if (!empty_vertex_array_) empty_vertex_array_ = gl::VertexArray::create(tracker_);
    return true;
}

// The programs this apply's way (path_) needs.
bool ObscurancePass::build_programs(ObscuranceMode mode, int samples, std::string& error) {
    return build_estimate(mode, samples, path_, error) && build_blur(path_, error) &&
           build_shared(mode, error);
}

// vo_compute 2: this frame's way from the trial for `key` (a new trial when the key changes),
// and the trial frame it runs (-1 when it runs none: decided, or waiting for the last times).
int ObscurancePass::choose_path(const TrialKey& key) {
    if (!(key == trial_key_)) {
        trial_.restart();
        trial_key_ = key;
        trial_issued_ = trial_read_ = 0;
    }
    read_trial();
    if (trial_.decided()) {
        path_ = trial_.choice();
        return -1;
    }
    if (trial_issued_ == StageTrial::kFrames) {  // waiting for the last frames' times
        path_ = StagePath::compute;
        return -1;
    }
    const int frame = trial_issued_++;
    path_ = StageTrial::path_of_frame(frame);
    return frame;
}

// The trial frames whose times have arrived, in order, into the trial; a decision counted.
void ObscurancePass::read_trial() {
    std::array<uint64_t, kTimedStages> nanoseconds{};
    while (trial_read_ < trial_issued_ && clock_.read(trial_read_, nanoseconds)) {
        trial_.record(trial_read_++, nanoseconds);
        if (trial_.decided()) ++decisions_;
    }
}

void ObscurancePass::stamp(int trial_frame, int stamp) {
    if (trial_frame >= 0) clock_.stamp(trial_frame, stamp);
}

namespace {

// The unit direction of (x, y); (1, 0) at the centre, where any does.
glm::vec2 unit_or_x(float x, float y) {
    const float length = std::sqrt(x * x + y * y);
    return length > 1e-6f ? glm::vec2(x, y) / length : glm::vec2(1.0f, 0.0f);
}

template <class Row>
float height_of(const Row& row) {
    if constexpr (requires { row.z; }) {
        return row.z;  // a point's: the turn keeps it
    } else {
        return 0.0f;  // a line's runs through the whole sphere
    }
}

// The largest k <= 12 such that turning the set by 2 pi / k about the view axis maps every
// sample onto one of the set (within 0.02): its rotational symmetry order, 1 for none.
template <class Row>
int symmetry_order(std::span<const Row> rows) {
    for (int k = 12; k > 1; --k) {
        const float angle = 6.2831853f / float(k);
        const float c = std::cos(angle), s = std::sin(angle);
        const bool maps = std::all_of(rows.begin(), rows.end(), [&](const Row& a) {
            const float x = c * a.x - s * a.y, y = s * a.x + c * a.y;
            return std::any_of(rows.begin(), rows.end(), [&](const Row& b) {
                return std::abs(b.x - x) + std::abs(b.y - y) +
                           std::abs(height_of(b) - height_of(a)) <
                       0.02f;
            });
        });
        if (maps) return k;
    }
    return 1;
}

// A line table as the estimate's uniforms: per line, what a turn keeps (x, y, its column's
// half-length on the unit sphere, its weight per unit of that length) in u_samples, and for
// the shift where it lies in the volume (its unit direction, the share of the sphere's volume
// in the columns nearer the centre, half its weight) in u_polar.
void set_line_uniforms(gl::Program& estimate, std::span<const LineSampleRow> rows) {
    std::array<float, 4 * kMaxLineSamples> lines{}, polar{};
    const size_t count = std::min(rows.size(), size_t(kMaxLineSamples));
    for (size_t i = 0; i < count; ++i) {
        const LineSampleRow& row = rows[i];
        const float r2 = std::min(row.x * row.x + row.y * row.y, 1.0f);
        const float column = std::sqrt(std::max(1.0f - r2, 1e-4f));
        const glm::vec2 direction = unit_or_x(row.x, row.y);
        const float share = 1.0f - (1.0f - r2) * std::sqrt(1.0f - r2);
        const float turned[] = {row.x, row.y, column, row.weight / (2.0f * column)};
        const float shifted[] = {direction.x, direction.y, share, 0.5f * row.weight};
        std::copy(turned, turned + 4, lines.begin() + std::ptrdiff_t(4 * i));
        std::copy(shifted, shifted + 4, polar.begin() + std::ptrdiff_t(4 * i));
    }
    glUniform4fv(estimate.location("u_samples"), GLsizei(count), lines.data());
    glUniform4fv(estimate.location("u_polar"), GLsizei(count), polar.data());
}

// A point table as the estimate's uniforms: the rows themselves (x, y, z, weight) in
// u_samples, and for the shift (its xy's unit direction, r^3, its height z / r) in u_polar.
void set_point_uniforms(gl::Program& estimate, std::span<const PointSampleRow> rows) {
    std::array<float, 4 * kMaxPointSamples> polar{};
    const size_t count = std::min(rows.size(), size_t(kMaxPointSamples));
    for (size_t i = 0; i < count; ++i) {
        const glm::vec3 p(rows[i].x, rows[i].y, rows[i].z);
        const float r = std::min(glm::length(p), 1.0f);
        const glm::vec2 direction = unit_or_x(p.x, p.y);
        const float height = r > 1e-6f ? std::clamp(p.z / r, -1.0f, 1.0f) : 0.0f;
        const float shifted[] = {direction.x, direction.y, r * r * r, height};
        std::copy(shifted, shifted + 4, polar.begin() + std::ptrdiff_t(4 * i));
    }
    glUniform4fv(estimate.location("u_samples"), GLsizei(count), &rows[0].x);
    glUniform4fv(estimate.location("u_polar"), GLsizei(count), polar.data());
}

}  // namespace

// The sample table of a lines or points mode, into its estimate program (in use), with the
// span its per-pixel turns cover.
void ObscurancePass::upload_samples(StagePrograms& programs, ObscuranceMode mode,
                                    SampleTableKey table) {
    gl::Program& estimate = programs.estimate[static_cast<size_t>(mode)];
    programs.uploaded[static_cast<size_t>(mode)] = table;
    constexpr float kFullTurn = 6.2831853f;
    float span = kFullTurn;
    // effective_sample_count only asks for tables that exist; an empty one uploads nothing.
    if (samples_lines(mode)) {
        const auto rows = line_sample_table(table.method, table.count);
        if (rows.empty()) return;
        set_line_uniforms(estimate, rows);
        span = kFullTurn / float(symmetry_order(rows));
    } else if (samples_points(mode)) {
        const auto rows = point_sample_table(table.method, table.count);
        if (rows.empty()) return;
        set_point_uniforms(estimate, rows);
        span = kFullTurn / float(symmetry_order(rows));
    }
    glUniform1f(estimate.location("u_rotation_span"), span);
}

// A render target of `levels` mip levels (linear filtering, clamped), its framebuffer on level 0.
// False with `error` when the driver refuses it.
bool ObscurancePass::make_target(Target& target, GLenum format, int levels, int width, int height,
                                 std::string& error) {
    target.texture = gl::Texture::create(tracker_);
    glBindTexture(GL_TEXTURE_2D, target.texture.id());
    glTexStorage2D(GL_TEXTURE_2D, levels, format, width, height);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER,
                    levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    target.framebuffer = gl::Framebuffer::create(tracker_);
    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target.texture.id(),
                           0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE) return true;
    error = std::string("obscurance: the driver refuses a ") +
            (format == GL_RG32F ? "RG32F" : "RGBA16F") + " render target";
    target = Target{};
    return false;
}

// RGBA16F: the estimate and the blur carry (open, distance, normal x, normal y).
bool ObscurancePass::prepare_targets(int width, int height, std::string& error) {
    if (targets_[0].texture && width == target_width_ && height == target_height_) return true;
    for (Target& target : targets_) {
        if (!make_target(target, GL_RGBA16F, 1, width, height, error)) {
            for (Target& t : targets_) t = Target{};
            return false;
        }
    }
    target_width_ = width;
    target_height_ = height;
    return true;
}

// RG32F: distance^2 reaches 4096^2, past what half floats hold.
bool ObscurancePass::prepare_moments(int width, int height, std::string& error) {
    if (moments_.texture && width == moments_width_ && height == moments_height_) return true;
    if (!make_target(moments_, GL_RG32F, kMomentsLevels, padded(width), padded(height), error)) {
        return false;
    }
    moments_width_ = width;
    moments_height_ = height;
    return true;
}

// Level 0 from the depth buffer, the rest averaged down: each level's texel holds the mean
// distance and mean squared distance of the scene texels under it.
void ObscurancePass::build_moments(const SceneTextures& scene) {
    bind_scene(moments_program_, scene);
    set_moments_scale(moments_program_, scene);
    glBindFramebuffer(GL_FRAMEBUFFER, moments_.framebuffer.id());
    glViewport(0, 0, padded(scene.width), padded(scene.height));
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindTexture(GL_TEXTURE_2D, moments_.texture.id());
    glGenerateMipmap(GL_TEXTURE_2D);
    bind_texture(kUnitMoments, moments_.texture.id());
}

void ObscurancePass::bind_scene(gl::Program& program, const SceneTextures& scene) {
    program.use();
    const float* p = scene.projection;
    glUniform4f(program.location("u_projection"), p[0], p[5], p[10], p[14]);
    glUniform2i(program.location("u_scene_size"), scene.width, scene.height);
    bind_texture(kUnitDepth, scene.depth_texture);
    bind_texture(kUnitNormal, scene.normal_texture);
}

void ObscurancePass::estimate(const SceneTextures& scene, const ObscuranceSettings& settings,
                              int samples) {
    StagePrograms& programs = stages_[size_t(path_)];
    gl::Program& program = programs.estimate[static_cast<size_t>(settings.mode)];
    bind_scene(program, scene);
    const SampleTableKey wanted{settings.sample_method, samples};
    if (programs.uploaded[static_cast<size_t>(settings.mode)] != wanted) {
        upload_samples(programs, settings.mode, wanted);
    }
    glUniform2f(program.location("u_radii"), settings.radius, settings.radius2);
    glUniform1i(program.location("u_dual_minimum"), settings.dual == DualRadius::minimum);
    glUniform1f(program.location("u_thickness"), settings.thickness);
    glUniform1i(program.location("u_normal_clamp"), settings.normal_clamp ? 1 : 0);
    glUniform1i(program.location("u_shift"), settings.shift ? 1 : 0);
    if (settings.mode == ObscuranceMode::area1) set_moments_scale(program, scene);
    glUniform2i(program.location("u_target_size"), target_width_, target_height_);
    run_stage(targets_[0], path_);
}

// The bound estimate or blur program over the whole target, into `to`.
void ObscurancePass::run_stage(const Target& to, StagePath path) {
    if (path == StagePath::compute) {
        glBindImageTexture(0, to.texture.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
        glDispatchCompute(GLuint((target_width_ + kComputeGroupSize - 1) / kComputeGroupSize),
                          GLuint((target_height_ + kComputeGroupSize - 1) / kComputeGroupSize), 1);
        // The next stage samples it; the next frame may draw into it as a framebuffer.
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
    } else {
        glBindFramebuffer(GL_FRAMEBUFFER, to.framebuffer.id());
        glViewport(0, 0, target_width_, target_height_);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    result_ = &to.texture;
}

void ObscurancePass::blur() {
    gl::Program& program = stages_[size_t(path_)].blur;
    program.use();
    const GLint step = program.location("u_step");
    for (int pass = 0; pass < 2; ++pass) {
        const Target& from = targets_[size_t(pass)];
        const Target& to = targets_[size_t(1 - pass)];
        glUniform2i(step, pass == 0 ? 1 : 0, pass == 0 ? 0 : 1);
        bind_texture(kUnitOpen, from.texture.id());
        run_stage(to, path_);
    }
}

void ObscurancePass::composite(const SceneTextures& scene, const ObscuranceSettings& settings,
                               const CompositeTarget* elsewhere) {
    bind_scene(composite_, scene);
    glUniform1f(composite_.location("u_strength"), settings.show ? 1.0f : settings.strength);
    glUniform1i(composite_.location("u_show"), settings.show ? 1 : 0);
    glUniform1i(composite_.location("u_copy"), elsewhere ? 1 : 0);
    bind_texture(kUnitOpen, result_->id());
    if (elsewhere) {  // colour * obscurance, written over the target
        bind_texture(kUnitColour, scene.colour_texture);
        glBindFramebuffer(GL_FRAMEBUFFER, elsewhere->framebuffer);
        const int* v = elsewhere->viewport;
        glViewport(v[0], v[1], v[2], v[3]);
        glDisable(GL_BLEND);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        return;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, scene.framebuffer);
    const GLenum colour_only = GL_COLOR_ATTACHMENT0;
    glDrawBuffers(1, &colour_only);
    glViewport(0, 0, scene.width, scene.height);
    if (settings.show) {
        glDisable(GL_BLEND);
    } else {
        glEnable(GL_BLEND);
        glBlendFunc(GL_ZERO, GL_SRC_COLOR);  // colour *= obscurance
    }
    glDrawArrays(GL_TRIANGLES, 0, 3);
    const GLenum both[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glDrawBuffers(2, both);
}

bool ObscurancePass::apply(const SceneTextures& scene, const ObscuranceSettings& settings,
                           std::string& error, const CompositeTarget* elsewhere) {
    if (scene.width <= 0 || scene.height <= 0) return true;
    const int samples = effective_sample_count(settings);
    const int width = settings.half_resolution ? (scene.width + 1) / 2 : scene.width;
    const int height = settings.half_resolution ? (scene.height + 1) / 2 : scene.height;
    if (gl_version_ == 0) gl_version_ = epoxy_gl_version();
    const bool blurs = settings.blur && settings.mode != ObscuranceMode::reference;
    int trial_frame = -1;
    if (settings.compute == ComputeUse::off || gl_version_ < 43 || compute_refused_) {
        path_ = StagePath::fragment;
    } else if (settings.compute == ComputeUse::on) {
        path_ = StagePath::compute;
    } else {
        trial_frame = choose_path({settings.mode, samples, width, height, blurs});
    }
    if (!build_programs(settings.mode, samples, error)) {
        // A driver that refuses the compute stages may still take the full-screen ones.
        if (path_ == StagePath::fragment) return false;
        compute_refused_ = true;
        error.clear();
        path_ = StagePath::fragment;
        trial_frame = -1;
        if (!build_programs(settings.mode, samples, error)) return false;
    }
    // A trial's first frame builds the other path's programs too, so that no later frame does.
    if (trial_frame == 0) {
        const StagePath other = StageTrial::path_of_frame(1);
        if (!build_estimate(settings.mode, samples, other, error) || !build_blur(other, error)) {
            return false;
        }
    }
    SavedState saved;
    if (!prepare_targets(width, height, error) ||
        (settings.mode == ObscuranceMode::area1 &&
         !prepare_moments(scene.width, scene.height, error))) {
        glBindFramebuffer(GL_FRAMEBUFFER, scene.framebuffer);
        return false;
    }
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glBindVertexArray(empty_vertex_array_.id());
    if (settings.mode == ObscuranceMode::area1) {
        mark_begin("vo_moments");
        build_moments(scene);
        mark_end();
    }
    stamp(trial_frame, 0);
    mark_begin("vo_estimate");
    estimate(scene, settings, samples);
    mark_end();
    stamp(trial_frame, 1);
    if (blurs) {
        mark_begin("vo_blur");
        blur();
        mark_end();
    }
    stamp(trial_frame, 2);
    mark_begin("vo_composite");
    composite(scene, settings, elsewhere);
    mark_end();
    if (path_ == StagePath::compute) {
        glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    }
    glBindVertexArray(0);
    glActiveTexture(GL_TEXTURE0);
    return true;
}

}  // namespace nq::npr::obscurance
