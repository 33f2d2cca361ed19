#include "classic/particle_drawer.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>

#include <glm/gtc/type_ptr.hpp>

#include "abi/abi_access.h"
#include "abi/frame_view.h"
#include "classic/classic_pass.h"

namespace nq::npr::classic {
namespace {

constexpr size_t kStreamBytes = 4 * 8192 * 16;  // 4 regions of 8192 particles

constexpr char kVertex[] = R"(#version 330 core
layout(location = 0) in vec3 a_origin;
layout(location = 1) in vec4 a_color;
uniform mat4 u_view_projection;
uniform vec3 u_eye;
uniform vec3 u_forward;
uniform vec3 u_right;
uniform vec3 u_up;
uniform float u_size;
out vec2 v_corner;
out vec4 v_color;
void main() {
    vec2 corner = vec2((gl_VertexID & 1) == 1 ? 0.5 : -0.5, gl_VertexID >= 2 ? 0.5 : -0.5);
    float depth = dot(a_origin - u_eye, u_forward);
    float scale = depth < 20.0 ? 1.0 : 1.0 + depth * 0.004;
    vec3 world = a_origin + (u_right * corner.x + u_up * corner.y) * (scale * u_size);
    gl_Position = u_view_projection * vec4(world, 1.0);
    v_corner = corner;
    v_color = a_color;
}
)";

constexpr char kFragment[] = R"(#version 330 core
in vec2 v_corner;
in vec4 v_color;
layout(location = 0) out vec4 o_color;
layout(location = 1) out vec4 o_normal;
void main() {
    float radius = length(v_corner) * 2.0;
    if (radius > 1.0) discard;
    float edge = clamp((1.0 - radius) * 4.0, 0.0, 1.0);
    o_color = vec4(v_color.rgb, v_color.a * edge);
    o_normal = vec4(0.5, 0.5, 1.0, 1.0);
}
)";

uint8_t alpha_byte(float alpha) {
    return static_cast<uint8_t>(std::lround(std::clamp(alpha, 0.0f, 1.0f) * 255.0f));
}

}  // namespace

bool ParticleDrawer::init(gl::ObjectTracker* tracker, const uint8_t* palette_rgb,
                          std::string& error, gl::StreamBuffer::Mode mode) {
    gl::ProgramBuild build = gl::Program::build({"classic particles", kVertex, kFragment}, tracker);
    if (!build.ok()) {
        error = build.error;
        return false;
    }
    program_ = std::move(build.program);
    palette_ = palette_rgb;
    if (!stream_.create(tracker, kStreamBytes, mode)) {
        error = "particle stream buffer: persistent mapping unavailable";
        return false;
    }
    vertex_array_ = gl::VertexArray::create(tracker);
    glBindVertexArray(vertex_array_.id());
    glEnableVertexAttribArray(0);
    glEnableVertexAttribArray(1);
    glVertexAttribDivisor(0, 1);
    glVertexAttribDivisor(1, 1);
    glBindVertexArray(0);
    return true;
}

void ParticleDrawer::reset() {
    stream_.reset();
    vertex_array_.reset();
    program_.reset();
}

void ParticleDrawer::draw_chunk(const nqr_frame& frame, uint32_t first, uint32_t count) {
    size_t offset = 0;
    auto* instances = static_cast<Instance*>(
        stream_.reserve(count * sizeof(Instance), sizeof(Instance), &offset));
    if (!instances) return;
    for (uint32_t i = 0; i < count; ++i) {
        const nqr_particle& source = abi_element(frame.particles, first + i);
        Instance& out = instances[i];
        std::copy(source.origin, source.origin + 3, out.origin);
        const uint8_t* colour = palette_ + source.color * 3;
        out.rgba[0] = colour[0];
        out.rgba[1] = colour[1];
        out.rgba[2] = colour[2];
        out.rgba[3] = alpha_byte(source.alpha);
    }
    stream_.unmap();
    glBindBuffer(GL_ARRAY_BUFFER, stream_.id());
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Instance),
                          reinterpret_cast<const void*>(offset));
    glVertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(Instance),
                          reinterpret_cast<const void*>(offset + offsetof(Instance, rgba)));
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(count));
}

void ParticleDrawer::draw_particles(const nqr_frame& frame) {
    FrameView view;
    if (!read_frame_view(&frame, view) || frame.num_particles == 0 || !program_ ||
        !has_known_prefix(frame.particles)) {
        return;
    }
    begin_classic_pass();
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    program_.use();
    glUniformMatrix4fv(program_.location("u_view_projection"), 1, GL_FALSE,
                       glm::value_ptr(view.view_projection));
    glUniform3fv(program_.location("u_eye"), 1, glm::value_ptr(view.eye));
    glUniform3fv(program_.location("u_forward"), 1, glm::value_ptr(view.forward));
    glUniform3fv(program_.location("u_right"), 1, glm::value_ptr(view.right));
    glUniform3fv(program_.location("u_up"), 1, glm::value_ptr(view.up));
    glUniform1f(program_.location("u_size"), kParticleSize);
    glBindVertexArray(vertex_array_.id());
    const auto per_chunk = static_cast<uint32_t>(stream_.max_push() / sizeof(Instance));
    for (uint32_t first = 0; first < frame.num_particles; first += per_chunk) {
        draw_chunk(frame, first, std::min(per_chunk, frame.num_particles - first));
    }
    end_classic_pass();
}

}  // namespace nq::npr::classic
