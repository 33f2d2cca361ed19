#include "obscurance/scene_triangles.h"

#include <algorithm>

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "abi/abi_access.h"

namespace nq::npr::obscurance {
namespace {

const nqr_model* find_model(std::span<const nqr_model* const> models, nqr_model_id id) {
    for (const nqr_model* m : models) {
        if (m && m->id == id) return m;
    }
    return nullptr;
}

// A brush model's surfaces [first, first + count), fanned into triangles, placed by
// `model_to_view`.
void add_brush(const nqr_model& model, const glm::mat4& model_to_view, ObscuranceScene& scene) {
    const nqr_brush_model* brush = model.brush;
    if (!brush || !brush->surfaces) return;
    const uint32_t end = std::min(model.first_surface + model.num_surfaces, brush->num_surfaces);
    for (uint32_t s = model.first_surface; s < end; ++s) {
        const nqr_surface& surface = npr::abi_element(brush->surfaces, s);
        if (surface.num_vertices < 3 ||
            surface.first_vertex + uint64_t(surface.num_vertices) > brush->num_vertices) {
            continue;
        }
        const bool solid = (surface.flags & (NQR_SURFACE_SKY | NQR_SURFACE_LIQUID)) == 0;
        const auto vertex = [&](uint32_t i) {
            const float* p = brush->positions + 3 * size_t(surface.first_vertex + i);
            return glm::vec3(model_to_view * glm::vec4(p[0], p[1], p[2], 1.0f));
        };
        const glm::vec3 first = vertex(0);
        for (uint32_t i = 1; i + 1 < surface.num_vertices; ++i) {
            scene.triangles.push_back({first, vertex(i), vertex(i + 1), solid});
        }
    }
}

// An alias entity's blended pose: model = scale * packed + origin, pose0 and pose1 mixed.
void add_alias(const nqr_entity& entity, const nqr_alias_model& alias,
               const glm::mat4& model_to_view, ObscuranceScene& scene) {
    if (!alias.poses || !alias.triangles || entity.pose0 >= alias.num_poses ||
        entity.pose1 >= alias.num_poses) {
        return;
    }
    const nqr_alias_vertex* pose0 = alias.poses + size_t(entity.pose0) * alias.num_vertices;
    const nqr_alias_vertex* pose1 = alias.poses + size_t(entity.pose1) * alias.num_vertices;
    const glm::vec3 scale = glm::make_vec3(alias.scale), origin = glm::make_vec3(alias.origin);
    const auto vertex = [&](uint32_t i) {
        const glm::vec3 a(pose0[i].v[0], pose0[i].v[1], pose0[i].v[2]);
        const glm::vec3 b(pose1[i].v[0], pose1[i].v[1], pose1[i].v[2]);
        const glm::vec3 p = scale * glm::mix(a, b, entity.lerp) + origin;
        return glm::vec3(model_to_view * glm::vec4(p, 1.0f));
    };
    for (uint32_t t = 0; t < alias.num_triangles; ++t) {
        const int32_t* tri = alias.triangles + 4 * size_t(t);
        if (std::any_of(tri + 1, tri + 4,
                        [&](int32_t v) { return v < 0 || uint32_t(v) >= alias.num_vertices; })) {
            continue;
        }
        scene.triangles.push_back(
            {vertex(uint32_t(tri[1])), vertex(uint32_t(tri[2])), vertex(uint32_t(tri[3])), true});
    }
}

}  // namespace

ObscuranceScene collect_scene(const nqr_frame& frame, std::span<const nqr_model* const> models) {
    ObscuranceScene scene;
    scene.width = uint32_t(std::max(frame.camera->viewport[2], 0));
    scene.height = uint32_t(std::max(frame.camera->viewport[3], 0));
    std::copy_n(frame.camera->projection, 16, scene.projection);
    const glm::mat4 view = glm::make_mat4(frame.camera->view);
    if (const nqr_model* world = find_model(models, frame.world)) add_brush(*world, view, scene);
    for (uint32_t i = 0; i < frame.num_brush_entities; ++i) {
        const nqr_entity* e = frame.brush_entities[i];
        if (!npr::entity_readable(e)) continue;
        const nqr_model* m = find_model(models, e->model);
        if (m && m->kind == NQR_MODEL_BRUSH) {
            add_brush(*m, view * glm::make_mat4(e->model_matrix), scene);
        }
    }
    for (uint32_t i = 0; i < frame.num_alias_entities; ++i) {
        const nqr_entity* e = frame.alias_entities[i];
        if (!npr::entity_readable(e) || (e->flags & NQR_ENTITY_VIEWMODEL) != 0) continue;
        const nqr_model* m = find_model(models, e->model);
        if (m && m->kind == NQR_MODEL_ALIAS && m->alias) {
            add_alias(*e, *m->alias, view * glm::make_mat4(e->model_matrix), scene);
        }
    }
    return scene;
}

}  // namespace nq::npr::obscurance
