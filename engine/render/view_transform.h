// Camera and entity transforms for the renderer ABI (nqr_camera, nqr_entity.model_matrix).
//
// Quake world space is right-handed: +X forward at yaw 0, +Y left, +Z up; angles are
// (pitch, yaw, roll) in degrees. GL eye space looks down -Z with +X right and +Y up. The view
// matrix maps Quake to GL axes as the ABI states: Quake +X (forward) -> GL -Z, +Y (left) -> GL
// -X, +Z (up) -> GL +Y, so projection * view * model goes from model space to clip space.
// Every matrix here is column-major (glm's layout, what glUniformMatrix4fv expects).
#pragma once

#include <glm/glm.hpp>

#include "nqr_renderer.h"

namespace nq {

// Quake's forward/right/up for (pitch, yaw, roll): yaw turns left about +Z, positive pitch looks
// DOWN (forward.z = -sin(pitch)), roll banks about forward. right = forward x up.
struct AngleVectors {
    glm::vec3 forward;
    glm::vec3 right;
    glm::vec3 up;
};
AngleVectors angle_vectors(const glm::vec3& angles);

// World -> GL eye space for an eye at `origin` looking along angle_vectors(angles).forward.
glm::mat4 view_matrix(const glm::vec3& origin, const glm::vec3& angles);

// Quake's vertical field of view for a horizontal one (degrees) on a viewport of width/height
// `aspect`: tan(fov_y / 2) = tan(fov_x / 2) / aspect.
float fov_y_from_fov_x(float fov_x_degrees, float aspect);
// A GL perspective projection (clip z in -w..w, as glFrustum) whose horizontal field of view
// is exactly fov_x; the vertical one follows from the aspect as above.
glm::mat4 perspective(float fov_x_degrees, float aspect, float z_near, float z_far);

// How an entity's pitch turns its model. Quake is inconsistent here, and GLQuake's drawers
// reproduce it: brush models and oriented sprites rotate like the view (positive pitch tips the
// nose down), alias models rotate the other way (positive pitch tips the nose up: GLQuake's
// R_RotateForEntity turns by -pitch, and negates brush pitch before calling it). The QuakeC
// relies on it: vectoangles() returns positive pitch for upward motion, and a rocket given
// those angles must point up.
enum class EntityPitch { like_view, alias_inverted };

// Model -> world: translate(origin) * Rz(yaw) * Ry(+/-pitch) * Rx(roll) * scale. Columns 0..2
// are the model's +X (forward), +Y (left) and +Z (up) in world space.
glm::mat4 model_matrix(const glm::vec3& origin, const glm::vec3& angles, float scale,
                       EntityPitch pitch);
// A world-space point in the space of `model` (inverse transform; model has no shear).
glm::vec3 world_to_model(const glm::mat4& model, const glm::vec3& world_point);

// What the engine knows about its view each frame.
struct CameraSetup {
    glm::vec3 origin{0.0f};
    glm::vec3 angles{0.0f};
    float fov_x = 90.0f;  // degrees
    float z_near = 4.0f;  // GLQuake's near plane
    float z_far = 16384.0f;
    int viewport[4] = {0, 0, 640, 480};  // x, y, width, height (GL: origin bottom-left)
};
// Fills every field of `out` (size included) from `setup`.
void fill_camera(const CameraSetup& setup, nqr_camera& out);

// Fills model_matrix and eye_model of `entity` from its origin, angles and scale (0 counts as 1)
// for a model of kind `kind` (nqr_model_kind), with the camera's eye.
void fill_entity_transform(uint32_t kind, const nqr_camera& camera, nqr_entity& entity);

// glm <-> the ABI's float arrays.
void store_matrix(const glm::mat4& m, float out[16]);
glm::mat4 load_matrix(const float m[16]);

}  // namespace nq
