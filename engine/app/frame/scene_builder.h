// Assembles the nqr_frame a renderer plugin draws: the camera, the world surfaces that survive
// PVS and frustum culling, light styles, and every visible entity with its model matrix, eye in
// model space and lighting, sorted by model kind. All storage is reserved once; building a
// frame does not allocate.
#pragma once

#include <array>
#include <vector>

#include "app/sessions/level.h"
#include "client/client_state.h"
#include "client/view.h"
#include "client/visible_entities.h"
#include "nqr_renderer.h"
#include "render/entity_lighting.h"
#include "render/frustum.h"
#include "render/light_list_smoother.h"
#include "render/light_smoother.h"
#include "render/view_transform.h"

namespace nq {

struct SceneCounts {
    uint32_t entities_considered = 0;
    uint32_t entities_culled = 0;        // outside the PVS: left out of the frame
    uint32_t entities_outside_view = 0;  // in the PVS, outside the frustum: flagged
    uint32_t entities_occluded = 0;      // on screen, hidden behind the world: flagged
    uint32_t entities_without_model = 0;
};

class SceneBuilder {
  public:
    static constexpr size_t kMaxEntities = 4096;
    static constexpr size_t kMaxParticles = 16384;
    static constexpr size_t kMaxDlights = 64;
    // Light smoothing state per entity number (numbers beyond it share slots modulo the size).
    static constexpr size_t kSmootherSlots = 8192;

    SceneBuilder();

    // Sizes the visible-surface list for the level's world (call after Level::load).
    void bind_level(Level& level);

    // Builds the frame for the client's current state.
    const nqr_frame& build(Level& level, const ClientState& client, const ViewResult& view,
                           const CameraSetup& camera, double real_time, float frame_time);

    // A frame from entities the caller provides (the showroom): no world, no culling.
    nqr_frame& begin_custom(const CameraSetup& camera, double time, double real_time,
                            float frame_time);
    nqr_entity& add_custom_entity(uint32_t kind);  // appended and listed under its kind
    // The lighting an entity of this frame points to (for custom frames to fill).
    EntityLighting& lighting(const nqr_entity& entity);
    const nqr_frame& finish_custom();

    // A frame that draws once everything the level can show: every world surface, one entity
    // of each alias and sprite model in front of the camera, a particle and a dynamic light.
    // Drawn (and then cleared) when a level or a renderer arrives, it makes the driver pay its
    // first-use costs (Mesa compiles a shader variant the first time a program draws with a
    // new texture or blend state) then, not in the frame where the first rocket explodes.
    const nqr_frame& build_warm_up(Level& level, const CameraSetup& camera);

    // Whether entities hidden behind the world are flagged NQR_ENTITY_OCCLUDED (r_occlusion).
    void set_occlusion_culling(bool enabled) { occlusion_enabled_ = enabled; }

    const SceneCounts& counts() const { return counts_; }
    VisibleEntityList& visible_entities() { return visible_; }

  private:
    void reset_lists();
    void set_view_frustum();  // frustum_ and frame_.view_planes from the camera
    void add_entity(Level& level, const ClientState& client, const VisibleEntity& v);
    bool pose_outside_view(const RenderModel& model, const nqr_entity& e) const;
    void add_occlusion_candidate(const RenderModel& model, nqr_entity& e);
    void add_brush_occluder(const RenderModel& model, const nqr_entity& e);
    void flag_occluded_entities();
    bool blend_pose_points(const nqr_alias_model& alias, const nqr_entity& e);
    void link_lists();

    nqr_frame frame_{};
    nqr_camera camera_{};  // frame_.camera points here
    std::vector<uint32_t> visible_surfaces_;
    std::array<float, 64> lightstyles_{};
    std::vector<nqr_entity> entities_;
    std::vector<EntityLighting> lighting_;  // entities_[i].light points to lighting_[i]
    size_t entity_count_ = 0;
    std::array<std::vector<const nqr_entity*>, 4> by_kind_;  // index: nqr_model_kind
    std::vector<nqr_particle> particles_;
    std::vector<nqr_dlight> dlights_;
    VisibleEntityList visible_;
    struct SmoothedLight {
        LightSmoother smoother;
        LightListSmoother lights;  // fades the strongest lights in and out (ABI 1.4)
        nqr_model_id model = 0;
    };
    std::vector<SmoothedLight> smoothed_;
    float light_dt_ = 0;
    Frustum frustum_;  // this frame's side planes
    bool occlusion_enabled_ = true;
    OcclusionCuller* occlusion_ = nullptr;  // this frame's, when culling by occlusion
    struct OcclusionCandidate {
        nqr_entity* entity;
        int32_t candidate;
        const nqr_alias_model* alias;
    };
    bool all_triangles_hidden(const OcclusionCandidate& c) const;
    std::vector<OcclusionCandidate> occlusion_candidates_;
    struct OccludingBrush {
        const nqr_entity* entity;
        const nqr_model* model;
    };
    std::vector<OccludingBrush> occluding_brushes_;
    const nqr_brush_model* world_brush_ = nullptr;  // brush entities of this map occlude
    std::vector<glm::vec3> pose_points_;            // one alias entity's blended vertices
    SceneCounts counts_;
};

}  // namespace nq
