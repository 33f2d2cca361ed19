#include "app/frame/scene_builder.h"

#include <algorithm>

#include "client/nqr_export.h"

namespace nq {

namespace {

glm::vec3 to_glm(const Vec3& v) {
    return {v[0], v[1], v[2]};
}

// Quake keeps the weapon and the player bright enough to be seen in the dark.
float minimum_light(const VisibleEntity& v, int view_entity) {
    if (v.flags & kVisibleViewModel) return kViewModelMinimumLight;
    if (static_cast<int>(v.number) == view_entity) return kPlayerMinimumLight;
    return 0.0f;
}

// The box holding an alias entity's blended pose this frame, in model space: blending moves each
// vertex between its places in the two poses, inside both poses' boxes' union.
bool frame_pose_box(const RenderModel& model, const nqr_entity& e,
                    AliasModelData::PoseBounds& box) {
    const AliasModelData* alias = model.alias_data();
    if (!alias) return false;
    const AliasModelData::PoseBounds a = alias->pose_bounds(e.pose0);
    const AliasModelData::PoseBounds b = alias->pose_bounds(e.pose1);
    box.mins = glm::min(a.mins, b.mins);
    box.maxs = glm::max(a.maxs, b.maxs);
    return true;
}

}  // namespace

SceneBuilder::SceneBuilder()
    : entities_(kMaxEntities),
      lighting_(kMaxEntities),
      particles_(kMaxParticles),
      dlights_(kMaxDlights),
      visible_(kMaxEntities),
      smoothed_(kSmootherSlots) {
    for (auto& list : by_kind_) list.reserve(kMaxEntities);
    occlusion_candidates_.reserve(kMaxEntities);
    occluding_brushes_.reserve(kMaxEntities);
    pose_points_.resize(1024);  // MDL's usual limit; a larger model grows it once
    frame_.size = sizeof(nqr_frame);
    camera_.size = sizeof(nqr_camera);
    frame_.camera = &camera_;
    lightstyles_.fill(1.0f);
}

EntityLighting& SceneBuilder::lighting(const nqr_entity& entity) {
    return lighting_[static_cast<size_t>(&entity - entities_.data())];
}

void SceneBuilder::bind_level(Level& level) {
    size_t n = level.culler() ? level.culler()->max_visible_surfaces() : 0;
    visible_surfaces_.assign(std::max<size_t>(n, 1), 0);
    for (auto& s : smoothed_) s = SmoothedLight{};
}

void SceneBuilder::reset_lists() {
    entity_count_ = 0;
    for (auto& list : by_kind_) list.clear();
    counts_ = {};
}

void SceneBuilder::link_lists() {
    frame_.brush_entities = by_kind_[NQR_MODEL_BRUSH].data();
    frame_.num_brush_entities = static_cast<uint32_t>(by_kind_[NQR_MODEL_BRUSH].size());
    frame_.alias_entities = by_kind_[NQR_MODEL_ALIAS].data();
    frame_.num_alias_entities = static_cast<uint32_t>(by_kind_[NQR_MODEL_ALIAS].size());
    frame_.sprite_entities = by_kind_[NQR_MODEL_SPRITE].data();
    frame_.num_sprite_entities = static_cast<uint32_t>(by_kind_[NQR_MODEL_SPRITE].size());
    frame_.lightstyles = lightstyles_.data();
}

const nqr_frame& SceneBuilder::build(Level& level, const ClientState& client,
                                     const ViewResult& view, const CameraSetup& camera,
                                     double real_time, float frame_time) {
    reset_lists();
    ++frame_.number;
    frame_.time = client.time();
    frame_.real_time = real_time;
    frame_.frame_time = frame_time;
    frame_.flags = (view.underwater ? uint32_t{NQR_FRAME_UNDERWATER} : 0u) |
                   (view.intermission ? uint32_t{NQR_FRAME_INTERMISSION} : 0u);
    fill_camera(camera, camera_);

    auto styles = client.light_style_values();
    std::copy(styles.begin(), styles.end(), lightstyles_.begin());

    frame_.num_dlights = static_cast<uint32_t>(
        export_dynamic_lights(client.dynamic_lights(), client.time(), dlights_));
    frame_.dlights = dlights_.data();
    frame_.num_particles =
        static_cast<uint32_t>(export_particles(client.particles().particles(), particles_));
    frame_.particles = particles_.data();

    frame_.world = level.model_id(1);
    frame_.num_visible_surfaces = 0;
    frame_.visible_surfaces = visible_surfaces_.data();
    set_view_frustum();
    if (WorldCuller* culler = level.culler()) {
        frame_.num_visible_surfaces =
            culler->cull(to_glm(view.origin), frustum_, visible_surfaces_);
    }

    light_dt_ = static_cast<float>(client.time() - client.old_time());
    occlusion_ = occlusion_enabled_ && level.culler() ? level.occlusion() : nullptr;
    occlusion_candidates_.clear();
    occluding_brushes_.clear();
    const RenderModel* world = level.models().get(level.model_id(1));
    world_brush_ = world ? world->abi()->brush : nullptr;
    if (occlusion_) occlusion_->begin_frame(camera_);
    collect_visible_entities(client, view, visible_);
    for (const VisibleEntity& v : visible_.entities()) add_entity(level, client, v);
    flag_occluded_entities();
    link_lists();
    return frame_;
}

void SceneBuilder::set_view_frustum() {
    frustum_ = Frustum::sides_from_view_projection(load_matrix(camera_.view_projection));
    for (size_t i = 0; i < std::size(frame_.view_planes); ++i) {
        const FrustumPlane& plane = frustum_.planes[i];
        frame_.view_planes[i][0] = plane.normal.x;
        frame_.view_planes[i][1] = plane.normal.y;
        frame_.view_planes[i][2] = plane.normal.z;
        frame_.view_planes[i][3] = plane.dist;
    }
}

// The radius sphere holds every pose at any angle; an alias model's two poses of this frame,
// placed, are often far smaller (a monster's sphere reaches into the view while the monster is
// off screen: every frame its faces, edges and shadows would be worked out for nothing).
bool SceneBuilder::pose_outside_view(const RenderModel& model, const nqr_entity& e) const {
    AliasModelData::PoseBounds box;
    return frame_pose_box(model, e, box) &&
           frustum_.placed_box_outside(load_matrix(e.model_matrix), box.mins, box.maxs);
}

// Alias models only: most of the edge and face work of a frame is theirs. Tested by the
// vertices of the pose drawn (a box's corners reach out of alcoves and past door frames the
// model itself stays behind).
void SceneBuilder::add_occlusion_candidate(const RenderModel& model, nqr_entity& e) {
    const AliasModelData* alias = model.alias_data();
    if (!occlusion_ || !alias || occlusion_candidates_.size() == kMaxEntities) return;
    const glm::mat4 placement = load_matrix(e.model_matrix);
    int32_t candidate = OcclusionCuller::kNotHideable;
    if (blend_pose_points(alias->abi(), e)) {
        candidate =
            occlusion_->add_points(placement, {pose_points_.data(), alias->abi().num_vertices});
    } else {
        AliasModelData::PoseBounds box;
        frame_pose_box(model, e, box);
        candidate = occlusion_->add_box(placement, box.mins, box.maxs);
    }
    if (candidate == OcclusionCuller::kOffScreen) {  // beyond a screen edge the box still met
        e.flags |= NQR_ENTITY_OUTSIDE_VIEW;
        ++counts_.entities_outside_view;
        return;
    }
    if (candidate != OcclusionCuller::kNotHideable) {
        occlusion_candidates_.push_back({&e, candidate, &alias->abi()});
    }
}

// The entity's pose as the plugins blend it, in model space; false when its poses or blend
// are out of range (then its box stands in).
bool SceneBuilder::blend_pose_points(const nqr_alias_model& a, const nqr_entity& e) {
    if (e.pose0 >= a.num_poses || e.pose1 >= a.num_poses || !(e.lerp >= 0.0f && e.lerp <= 1.0f) ||
        a.num_vertices == 0) {
        return false;
    }
    if (pose_points_.size() < a.num_vertices) pose_points_.resize(a.num_vertices);  // once
    const nqr_alias_vertex* pose0 = a.poses + size_t(e.pose0) * a.num_vertices;
    const nqr_alias_vertex* pose1 = a.poses + size_t(e.pose1) * a.num_vertices;
    const glm::vec3 scale(a.scale[0], a.scale[1], a.scale[2]);
    const glm::vec3 origin(a.origin[0], a.origin[1], a.origin[2]);
    for (uint32_t v = 0; v < a.num_vertices; ++v) {
        const glm::vec3 p0(pose0[v].v[0], pose0[v].v[1], pose0[v].v[2]);
        const glm::vec3 p1(pose1[v].v[0], pose1[v].v[1], pose1[v].v[2]);
        pose_points_[v] = scale * (p0 + (p1 - p0) * e.lerp) + origin;
    }
    return true;
}

// Brush entities of the map itself (doors, platforms, walls that move), drawn opaque with depth
// writes, hide what is behind them as the world does; translucent ones do not, nor models from
// other files (item boxes).
void SceneBuilder::add_brush_occluder(const RenderModel& model, const nqr_entity& e) {
    const nqr_model& abi = *model.abi();
    const bool opaque = e.alpha <= 0.0f || e.alpha >= 1.0f;
    if (!occlusion_ || abi.kind != NQR_MODEL_BRUSH || abi.brush == nullptr ||
        abi.brush != world_brush_ || !opaque || occluding_brushes_.size() == kMaxEntities) {
        return;
    }
    occluding_brushes_.push_back({&e, &abi});
}

// A model in an alcove or behind a door often has farther pixels inside its screen rectangle
// but beside it; its triangles one by one are hidden.
bool SceneBuilder::all_triangles_hidden(const OcclusionCandidate& c) const {
    if (c.alias == nullptr || c.alias->num_triangles == 0) return false;
    for (uint32_t t = 0; t < c.alias->num_triangles; ++t) {
        const int32_t* record = c.alias->triangles + size_t(t) * 4;  // facesfront, v0, v1, v2
        if (record[1] < 0 || record[2] < 0 || record[3] < 0 ||
            !occlusion_->triangle_hidden(c.candidate, uint32_t(record[1]), uint32_t(record[2]),
                                         uint32_t(record[3]))) {
            return false;
        }
    }
    return true;
}

void SceneBuilder::flag_occluded_entities() {
    if (!occlusion_ || occlusion_candidates_.empty()) return;
    occlusion_->rasterize_world({visible_surfaces_.data(), frame_.num_visible_surfaces});
    for (const OccludingBrush& b : occluding_brushes_) {
        const nqr_entity& e = *b.entity;
        occlusion_->rasterize_model(b.model->first_surface, b.model->num_surfaces,
                                    load_matrix(e.model_matrix),
                                    glm::vec3(e.eye_model[0], e.eye_model[1], e.eye_model[2]));
    }
    for (const OcclusionCandidate& c : occlusion_candidates_) {
        if (!occlusion_->hidden(c.candidate) && !all_triangles_hidden(c)) continue;
        c.entity->flags |= NQR_ENTITY_OCCLUDED;
        ++counts_.entities_occluded;
    }
}

void SceneBuilder::add_entity(Level& level, const ClientState& client, const VisibleEntity& v) {
    ++counts_.entities_considered;
    nqr_model_id id = level.model_id(v.model);
    uint32_t kind = level.model_kind(id);
    if (id == 0 || kind == 0 || kind > NQR_MODEL_SPRITE) {
        ++counts_.entities_without_model;
        return;
    }
    const RenderModel* model = level.models().get(id);
    // Conservative bounds: the model's radius around its origin, rotation-proof.
    const float radius = std::max(model->abi()->radius, 1.0f) * std::max(v.scale, 1.0f);
    const glm::vec3 origin = to_glm(v.origin);
    const bool view_model = (v.flags & kVisibleViewModel) != 0;
    if (!view_model && level.culler() &&
        !level.culler()->box_potentially_visible(origin - radius, origin + radius)) {
        ++counts_.entities_culled;
        return;
    }
    if (entity_count_ == entities_.size()) return;
    nqr_entity& e = entities_[entity_count_++];
    EntityLighting& light = lighting_[entity_count_ - 1];
    export_entity(v, id, e);
    e.light = &light;
    fill_entity_transform(kind, camera_, e);
    // Kept, flagged: a plugin may still want it for what reaches into the view (shadows).
    if (!view_model && (frustum_.sphere_outside(origin, radius) || pose_outside_view(*model, e))) {
        e.flags |= NQR_ENTITY_OUTSIDE_VIEW;
        ++counts_.entities_outside_view;
    } else if (!view_model) {
        add_occlusion_candidate(*model, e);
        add_brush_occluder(*model, e);
    }
    if (const LightSampler* sampler = level.light_sampler()) {
        EntityLightQuery query;
        query.origin = to_glm(v.origin);
        query.minimum_level = minimum_light(v, client.view_entity());
        query.fullbright = (v.flags & kVisibleFullbright) != 0;
        LightContributions strongest;
        sampler->sample(query, lightstyles_, DlightList{dlights_.data(), frame_.num_dlights}, light,
                        &strongest);
        // Smoothed per entity so its light never snaps (e.g. crossing a shadow edge) and its
        // lights fade in and out of its list.
        SmoothedLight& slot = smoothed_[v.number % smoothed_.size()];
        if (slot.model != id) {
            slot.smoother.reset();
            slot.lights.reset();
            slot.model = id;
        }
        slot.smoother.update(light, light_dt_, light);
        slot.lights.update(strongest, light_dt_, light);
    }
    by_kind_[kind].push_back(&e);
}

nqr_frame& SceneBuilder::begin_custom(const CameraSetup& camera, double time, double real_time,
                                      float frame_time) {
    reset_lists();
    ++frame_.number;
    frame_.time = time;
    frame_.real_time = real_time;
    frame_.frame_time = frame_time;
    frame_.flags = 0;
    fill_camera(camera, camera_);
    set_view_frustum();
    occlusion_ = nullptr;
    lightstyles_.fill(1.0f);
    frame_.world = 0;
    frame_.num_visible_surfaces = 0;
    frame_.visible_surfaces = visible_surfaces_.empty() ? nullptr : visible_surfaces_.data();
    frame_.num_dlights = 0;
    frame_.dlights = dlights_.data();
    frame_.num_particles = 0;
    frame_.particles = particles_.data();
    return frame_;
}

nqr_entity& SceneBuilder::add_custom_entity(uint32_t kind) {
    const size_t index = std::min(entity_count_, entities_.size() - 1);
    if (entity_count_ < entities_.size()) ++entity_count_;
    nqr_entity& e = entities_[index];
    e = nqr_entity{};
    e.size = sizeof(nqr_entity);
    lighting_[index] = EntityLighting{};
    e.light = &lighting_[index];
    if (kind >= 1 && kind <= NQR_MODEL_SPRITE) by_kind_[kind].push_back(&e);
    return e;
}

const nqr_frame& SceneBuilder::finish_custom() {
    link_lists();
    return frame_;
}

const nqr_frame& SceneBuilder::build_warm_up(Level& level, const CameraSetup& camera) {
    // Numbers no server entity uses, so plugins' per-entity state does not mix them up.
    constexpr uint32_t kFirstWarmUpNumber = 0x7fff0000u;
    // Quake counts every world leaf visible from outside the map; no frustum culls here.
    const glm::vec3 outside_any_map(1.0e6f, 1.0e6f, 1.0e6f);
    nqr_frame& frame = begin_custom(camera, 0.0, 0.0, 0.0f);
    if (const RenderModel* world = level.models().world(); world && level.culler()) {
        frame.world = world->id();
        frame.num_visible_surfaces =
            level.culler()->cull(outside_any_map, Frustum{}, visible_surfaces_);
    }
    const glm::mat4 view = load_matrix(camera_.view);
    const glm::vec3 forward = -glm::vec3(view[0][2], view[1][2], view[2][2]);
    const glm::vec3 ahead = camera.origin + forward * 64.0f;
    uint32_t number = kFirstWarmUpNumber;
    for (const auto& model : level.models().models()) {
        const uint32_t kind = model->kind();
        if (kind != NQR_MODEL_ALIAS && kind != NQR_MODEL_SPRITE) continue;
        nqr_entity& e = add_custom_entity(kind);
        e.model = model->id();
        e.number = number++;
        e.origin[0] = ahead.x;
        e.origin[1] = ahead.y;
        e.origin[2] = ahead.z;
        e.scale = 1;
        e.alpha = 1;
        fill_entity_transform(kind, camera_, e);
        EntityLighting& light = lighting(e);
        light.ambient = 1;
        for (auto& face : light.ambient_cube) face[0] = face[1] = face[2] = 1;
        light.color[0] = light.color[1] = light.color[2] = 1;
    }
    particles_[0] = nqr_particle{sizeof(nqr_particle), {ahead.x, ahead.y, ahead.z}, 15, {}, 1};
    frame.num_particles = 1;
    dlights_[0] = nqr_dlight{sizeof(nqr_dlight), {ahead.x, ahead.y, ahead.z}, 200, {1, 1, 1}};
    frame.num_dlights = 1;
    return finish_custom();
}

}  // namespace nq
