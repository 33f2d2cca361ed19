#include "render/view_transform.h"

#include <cmath>

namespace nq {

namespace {

constexpr float kPi = 3.14159265358979323846f;

float radians(float degrees) {
    return degrees * (kPi / 180.0f);
}

glm::vec3 vec3_from(const float v[3]) {
    return {v[0], v[1], v[2]};
}

void store_vec3(const glm::vec3& v, float out[3]) {
    out[0] = v.x;
    out[1] = v.y;
    out[2] = v.z;
}

}  // namespace

AngleVectors angle_vectors(const glm::vec3& angles) {
    const float sp = std::sin(radians(angles.x)), cp = std::cos(radians(angles.x));
    const float sy = std::sin(radians(angles.y)), cy = std::cos(radians(angles.y));
    const float sr = std::sin(radians(angles.z)), cr = std::cos(radians(angles.z));
    AngleVectors v;
    v.forward = {cp * cy, cp * sy, -sp};
    v.right = {-sr * sp * cy + cr * sy, -sr * sp * sy - cr * cy, -sr * cp};
    v.up = {cr * sp * cy + sr * sy, cr * sp * sy - sr * cy, cr * cp};
    return v;
}

glm::mat4 view_matrix(const glm::vec3& origin, const glm::vec3& angles) {
    const AngleVectors v = angle_vectors(angles);
    // Rows of the rotation are the GL eye axes expressed in Quake world space:
    // eye +X = right, eye +Y = up, eye +Z = -forward (GL looks down -Z).
    const glm::vec3 rows[3] = {v.right, v.up, -v.forward};
    glm::mat4 m(1.0f);
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) m[c][r] = rows[r][c];
        m[3][r] = -glm::dot(rows[r], origin);
    }
    return m;
}

float fov_y_from_fov_x(float fov_x_degrees, float aspect) {
    const float half_x = std::tan(radians(fov_x_degrees) * 0.5f);
    return 2.0f * std::atan(half_x / aspect) * (180.0f / kPi);
}

glm::mat4 perspective(float fov_x_degrees, float aspect, float z_near, float z_far) {
    const float x_scale = 1.0f / std::tan(radians(fov_x_degrees) * 0.5f);
    const float y_scale = x_scale * aspect;  // = 1 / tan(fov_y / 2)
    glm::mat4 m(0.0f);
    m[0][0] = x_scale;
    m[1][1] = y_scale;
    m[2][2] = (z_far + z_near) / (z_near - z_far);
    m[2][3] = -1.0f;
    m[3][2] = 2.0f * z_far * z_near / (z_near - z_far);
    return m;
}

glm::mat4 model_matrix(const glm::vec3& origin, const glm::vec3& angles, float scale,
                       EntityPitch pitch) {
    const float applied_pitch = pitch == EntityPitch::alias_inverted ? -angles.x : angles.x;
    // Rz(yaw) * Ry(pitch) * Rx(roll) has the same columns as Quake's angle vectors:
    // forward, left (= -right) and up.
    const AngleVectors v = angle_vectors({applied_pitch, angles.y, angles.z});
    glm::mat4 m(1.0f);
    m[0] = glm::vec4(v.forward * scale, 0.0f);
    m[1] = glm::vec4(-v.right * scale, 0.0f);
    m[2] = glm::vec4(v.up * scale, 0.0f);
    m[3] = glm::vec4(origin, 1.0f);
    return m;
}

glm::vec3 world_to_model(const glm::mat4& model, const glm::vec3& world_point) {
    return glm::vec3(glm::inverse(model) * glm::vec4(world_point, 1.0f));
}

void fill_camera(const CameraSetup& setup, nqr_camera& out) {
    out = nqr_camera{};
    out.size = sizeof(nqr_camera);
    store_vec3(setup.origin, out.origin);
    store_vec3(setup.angles, out.angles);
    const AngleVectors v = angle_vectors(setup.angles);
    store_vec3(v.forward, out.forward);
    store_vec3(v.right, out.right);
    store_vec3(v.up, out.up);

    const int width = setup.viewport[2] > 0 ? setup.viewport[2] : 1;
    const int height = setup.viewport[3] > 0 ? setup.viewport[3] : 1;
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    const glm::mat4 view = view_matrix(setup.origin, setup.angles);
    const glm::mat4 projection = perspective(setup.fov_x, aspect, setup.z_near, setup.z_far);
    store_matrix(view, out.view);
    store_matrix(projection, out.projection);
    store_matrix(projection * view, out.view_projection);
    out.fov_x = setup.fov_x;
    out.fov_y = fov_y_from_fov_x(setup.fov_x, aspect);
    out.z_near = setup.z_near;
    out.z_far = setup.z_far;
    for (int i = 0; i < 4; ++i) out.viewport[i] = setup.viewport[i];
}

void fill_entity_transform(uint32_t kind, const nqr_camera& camera, nqr_entity& entity) {
    const EntityPitch pitch =
        kind == NQR_MODEL_ALIAS ? EntityPitch::alias_inverted : EntityPitch::like_view;
    const float scale = entity.scale > 0.0f ? entity.scale : 1.0f;
    const glm::mat4 model =
        model_matrix(vec3_from(entity.origin), vec3_from(entity.angles), scale, pitch);
    store_matrix(model, entity.model_matrix);
    store_vec3(world_to_model(model, vec3_from(camera.origin)), entity.eye_model);
}

void store_matrix(const glm::mat4& m, float out[16]) {
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) out[c * 4 + r] = m[c][r];
    }
}

glm::mat4 load_matrix(const float m[16]) {
    glm::mat4 out;
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) out[c][r] = m[c * 4 + r];
    }
    return out;
}

}  // namespace nq
