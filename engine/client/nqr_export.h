// Copies client output into the renderer ABI's structs (nqr_renderer.h). Only what the client
// knows is written: the engine still fills model ids' meaning, matrices, eye_model, lighting,
// projection and viewport. Nothing here allocates.
#pragma once

#include <cstddef>
#include <span>

#include "client/dynamic_lights.h"
#include "client/particle_system.h"
#include "client/view.h"
#include "client/visible_entities.h"
#include "nqr_renderer.h"

namespace nq {

// Fills the entity fields the client owns (size, number, model, flags, origin, angles, scale,
// frame, poses, lerp, skin, colours, alpha, effects). `model` is the engine's id for
// v.model. Fields the engine computes (model_matrix, eye_model, light) are left untouched.
void export_entity(const VisibleEntity& v, nqr_model_id model, nqr_entity& out);

// Writes the eye, angles and basis vectors; matrices, fov and viewport are the engine's.
void export_camera_pose(const ViewResult& view, nqr_camera& out);

// Copies as many as fit; returns how many were written.
size_t export_particles(std::span<const Particle> particles, std::span<nqr_particle> out);
size_t export_dynamic_lights(const DynamicLights& lights, double time, std::span<nqr_dlight> out);

}  // namespace nq
