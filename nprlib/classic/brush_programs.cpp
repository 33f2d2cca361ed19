#include "classic/brush_programs.h"

#include <string>

namespace nq::npr::classic {
namespace {

constexpr char kVertex[] = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec2 a_texel;
layout(location = 2) in vec3 a_lightmap;
layout(location = 3) in vec3 a_normal;
uniform mat4 u_view_projection;
uniform mat4 u_model;
uniform mat3 u_normal_to_view;
uniform vec2 u_texture_size;
out vec2 v_uv;
out vec2 v_texel;
out vec3 v_lightmap;
out vec3 v_normal;
out vec3 v_world;
void main() {
    vec4 world = u_model * vec4(a_position, 1.0);
    gl_Position = u_view_projection * world;
    v_texel = a_texel;
    v_uv = a_texel / u_texture_size;
    v_lightmap = a_lightmap;
    v_normal = u_normal_to_view * a_normal;
    v_world = world.xyz;
}
)";

// What every brush fragment shader shares: the vertex shader's outputs, the two targets, and
// the view-space normal written to the second one; its alpha says whether the surface is solid
// (1) or sky or liquid (0: water, slime, lava and teleporters are not solid, so screen-space
// obscurance leaves them alone, as the clear colour's alpha does for the void).
constexpr char kFragmentHeader[] = R"(#version 330 core
in vec2 v_uv;
in vec2 v_texel;
in vec3 v_lightmap;
in vec3 v_normal;
in vec3 v_world;
layout(location = 0) out vec4 o_color;
layout(location = 1) out vec4 o_normal;
void write_normal(float solid) { o_normal = vec4(normalize(v_normal) * 0.5 + 0.5, solid); }
)";

constexpr char kLitFragment[] = R"(
uniform sampler2D u_texture;
uniform sampler2D u_fullbright;
uniform sampler2DArray u_lightmap;
uniform float u_overbright;
uniform float u_alpha;
uniform float u_alpha_cutoff;
void main() {
    vec4 base = texture(u_texture, v_uv);
    if (base.a < u_alpha_cutoff) discard;
    vec3 light = texture(u_lightmap, v_lightmap).rgb * u_overbright;
    vec3 color = base.rgb * light + texture(u_fullbright, v_uv).rgb;
    o_color = vec4(color, u_alpha);
    write_normal(1.0);
}
)";

// Quake's sky: the view direction to the surface, flattened (z x 3) and pushed out to a sphere
// of radius 6 x 63, gives the layer coordinates in 128-texel units; the back layer scrolls at 8
// and the front at 16 units a second (the scroll arrives in u_scroll, wrapped on the CPU).
constexpr char kSkyFragment[] = R"(
uniform sampler2D u_texture;
uniform sampler2D u_fullbright;
uniform vec3 u_eye;
uniform vec2 u_scroll;
uniform float u_alpha;
void main() {
    vec3 direction = v_world - u_eye;
    direction.z *= 3.0;
    vec2 sphere = normalize(direction).xy * (6.0 * 63.0);
    vec4 back = texture(u_texture, (u_scroll.x + sphere) / 128.0);
    vec4 front = texture(u_fullbright, (u_scroll.y + sphere) / 128.0);
    o_color = vec4(mix(back.rgb, front.rgb, front.a), u_alpha);
    write_normal(0.0);
}
)";

// Quake's turbulence: s' = s + 8 sin(t / 8 + time), t' = t + 8 sin(s / 8 + time), in texels.
constexpr char kLiquidFragment[] = R"(
uniform sampler2D u_texture;
uniform vec2 u_texture_size;
uniform float u_time;
uniform float u_alpha;
void main() {
    vec2 warped = v_texel + 8.0 * sin(v_texel.yx * 0.125 + u_time);
    o_color = vec4(texture(u_texture, warped / u_texture_size).rgb, u_alpha);
    write_normal(0.0);
}
)";

bool build_one(gl::Program& out, const char* name, const char* fragment_body,
               gl::ObjectTracker* tracker, std::string& error) {
    const std::string fragment = std::string(kFragmentHeader) + fragment_body;
    gl::ProgramBuild build = gl::Program::build({name, kVertex, fragment.c_str()}, tracker);
    if (!build.ok()) {
        error = build.error;
        return false;
    }
    out = std::move(build.program);
    gl::bind_sampler_units(out, {"u_texture", "u_fullbright", "u_lightmap"});
    return true;
}

}  // namespace

bool BrushPrograms::build(gl::ObjectTracker* tracker, std::string& error) {
    return build_one(lit, "classic brush (lit)", kLitFragment, tracker, error) &&
           build_one(sky, "classic brush (sky)", kSkyFragment, tracker, error) &&
           build_one(liquid, "classic brush (liquid)", kLiquidFragment, tracker, error);
}

void BrushPrograms::reset() {
    lit.reset();
    sky.reset();
    liquid.reset();
}

}  // namespace nq::npr::classic
