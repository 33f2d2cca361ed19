#include "classic/alias_pose_glsl.h"

#include <epoxy/gl.h>

#include <algorithm>

namespace nq::npr::classic {

const char* const kAliasPoseLibrary = R"(
uniform usamplerBuffer u_poses;
uniform int u_num_vertices;
uniform int u_pose0;
uniform int u_pose1;
uniform float u_lerp;
uniform vec3 u_scale;
uniform vec3 u_origin;
int pose_texel(int pose, int mdl_vertex) { return (pose * u_num_vertices + mdl_vertex) * 2; }
vec3 unpack_pose_normal(uvec4 texel) { return (vec3(texel.xyz) - 127.5) / 127.5; }
vec3 pose_position(int mdl_vertex) {
    uvec4 p0 = texelFetch(u_poses, pose_texel(u_pose0, mdl_vertex));
    uvec4 p1 = texelFetch(u_poses, pose_texel(u_pose1, mdl_vertex));
    return u_scale * mix(vec3(p0.xyz), vec3(p1.xyz), u_lerp) + u_origin;
}
vec3 pose_normal(int mdl_vertex) {
    vec3 n0 = unpack_pose_normal(texelFetch(u_poses, pose_texel(u_pose0, mdl_vertex) + 1));
    vec3 n1 = unpack_pose_normal(texelFetch(u_poses, pose_texel(u_pose1, mdl_vertex) + 1));
    return mix(n0, n1, u_lerp);
}
)";

void set_alias_pose_uniforms(gl::Program& program, const AliasModelGpu& model,
                             const nqr_entity& entity, int unit) {
    const nqr_alias_model& source = model.model();
    const uint32_t last_pose = source.num_poses - 1;
    glUniform1i(program.location("u_num_vertices"), static_cast<GLint>(source.num_vertices));
    glUniform1i(program.location("u_pose0"), static_cast<GLint>(std::min(entity.pose0, last_pose)));
    glUniform1i(program.location("u_pose1"), static_cast<GLint>(std::min(entity.pose1, last_pose)));
    glUniform1f(program.location("u_lerp"), std::clamp(entity.lerp, 0.0f, 1.0f));
    glUniform3fv(program.location("u_scale"), 1, source.scale);
    glUniform3fv(program.location("u_origin"), 1, source.origin);
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_BUFFER, model.pose_texture());
}

}  // namespace nq::npr::classic
