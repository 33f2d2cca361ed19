// The built-in showroom: a lit checkerboard floor and procedural models (cube, step, sphere,
// torus) turning under one light. Shown with `+showroom`, or when no game data is found, so
// every renderer plugin can be seen and tested without any data. The geometry is known exactly,
// which makes it the scene of choice for render tests.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "app/frame/scene_builder.h"
#include "app/frame/showroom_meshes.h"
#include "nqr_renderer.h"
#include "render/entity_lighting.h"

namespace nq {

class Showroom {
  public:
    static constexpr float kFloorHalfSize = 512.0f;
    static constexpr float kLightHeight = 320.0f;
    static constexpr float kModelSize = 64.0f;
    static constexpr float kOrbitRadius = 112.0f;
    static constexpr float kTurnDegreesPerSecond = 30.0f;

    Showroom();
    ~Showroom();

    // Models to register with the renderer (the floor first); ids start at `first_id`.
    void assign_ids(nqr_model_id first_id);
    std::vector<const nqr_model*> models() const;

    // The showroom's own palette (16 hue ramps), for when no game palette is loaded.
    static std::array<uint8_t, 768> builtin_palette();

    // Fills the frame for time `time` seen by `camera` (a default camera when none given).
    const nqr_frame& build(SceneBuilder& scene, const CameraSetup& camera, double time,
                           double real_time, float frame_time) const;
    // The default camera: looking at the models from above and in front.
    static CameraSetup default_camera(int width, int height);

    std::array<float, 3> light_position() const { return {0.0f, 0.0f, kLightHeight}; }
    // Where model `i` (0..3) stands at time `time`, and its yaw in degrees.
    std::array<float, 3> model_origin(size_t i) const;
    float model_yaw(double time) const;
    size_t model_count() const { return alias_.size(); }

    // The engine's trace service while the showroom is shown: the floor is the top (z = 0) of
    // a solid slab under the floor square; everything else is open space.
    static void trace(const float start[3], const float end[3], nqr_trace* out);

  private:
    struct AliasStorage;
    struct FloorStorage;

    void fill_light(const std::array<float, 3>& at, EntityLighting& out) const;

    std::unique_ptr<FloorStorage> floor_;
    std::vector<std::unique_ptr<AliasStorage>> alias_;
};

}  // namespace nq
