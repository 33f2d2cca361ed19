#include "classic/world_drawer.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "abi/abi_access.h"
#include "abi/frame_view.h"
#include "classic/classic_pass.h"
#include "gl/texture_upload.h"

namespace nq::npr::classic {
namespace {

constexpr double kTwoPi = 6.283185307179586;
constexpr double kSkyBackSpeed = 8.0;        // units per second
constexpr double kSkyFrontSpeed = 16.0;      // units per second
constexpr double kSkyLayerSize = 128.0;      // scroll wraps every layer width
constexpr float kFenceAlphaCutoff = 0.666f;  // GLQuake's alpha test threshold

void bind_texture(int unit, GLenum target, GLuint texture) {
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(target, texture);
}

bool kind_matches(SurfaceKind batch_kind, SurfaceKind wanted) {
    if (wanted == SurfaceKind::lit) {
        return batch_kind == SurfaceKind::lit || batch_kind == SurfaceKind::fence;
    }
    return batch_kind == wanted;
}

}  // namespace

bool WorldDrawer::init(gl::ObjectTracker* tracker, std::string& error) {
    black_ = gl::create_solid_texture(tracker, 0, 0, 0, 0);
    return programs_.build(tracker, error);
}

void WorldDrawer::reset() {
    programs_.reset();
    black_.reset();
}

std::span<const DynamicLight> WorldDrawer::gather_lights(const nqr_frame& frame,
                                                         const glm::mat4& model_matrix) {
    if (frame.num_dlights == 0 || !has_known_prefix(frame.dlights)) return {};
    const glm::mat4 to_model = glm::inverse(model_matrix);
    size_t count = 0;
    for (uint32_t i = 0; i < frame.num_dlights && count < lights_.size(); ++i) {
        const nqr_dlight& source = abi_element(frame.dlights, i);
        if (source.radius <= 0.0f) continue;
        const glm::vec4 origin = to_model * glm::vec4(glm::make_vec3(source.origin), 1.0f);
        DynamicLight& light = lights_[count++];
        light = {{origin.x, origin.y, origin.z},
                 source.radius,
                 {source.color[0], source.color[1], source.color[2]}};
    }
    return {lights_.data(), count};
}

void WorldDrawer::set_common_uniforms(gl::Program& program, const FrameView& view,
                                      const glm::mat4& model_matrix) {
    program.use();
    glUniformMatrix4fv(program.location("u_view_projection"), 1, GL_FALSE,
                       glm::value_ptr(view.view_projection));
    glUniformMatrix4fv(program.location("u_model"), 1, GL_FALSE, glm::value_ptr(model_matrix));
    const glm::mat3 normals = normal_to_view(view, model_matrix);
    glUniformMatrix3fv(program.location("u_normal_to_view"), 1, GL_FALSE, glm::value_ptr(normals));
}

void WorldDrawer::draw_kind(BrushModelGpu& model, const SurfaceBatches& batches, SurfaceKind kind,
                            gl::Program& program) {
    for (const SurfaceBatch& batch : batches.batches()) {
        const BrushTextureGpu& texture = model.texture_slot(batch.texture_slot);
        if (!kind_matches(texture.kind, kind)) continue;
        glUniform2f(program.location("u_texture_size"), texture.size[0], texture.size[1]);
        bind_texture(kUnitTexture, GL_TEXTURE_2D, texture.base.id());
        if (kind == SurfaceKind::lit) {
            glUniform1f(program.location("u_alpha_cutoff"),
                        texture.kind == SurfaceKind::fence ? kFenceAlphaCutoff : 0.0f);
            bind_texture(kUnitFullbright, GL_TEXTURE_2D,
                         texture.fullbright ? texture.fullbright.id() : black_.id());
        } else if (kind == SurfaceKind::sky) {
            bind_texture(kUnitFullbright, GL_TEXTURE_2D, texture.sky_front.id());
        }
        glMultiDrawElements(GL_TRIANGLES, batches.counts() + batch.first, GL_UNSIGNED_INT,
                            batches.offsets() + batch.first, static_cast<GLsizei>(batch.count));
    }
}

void WorldDrawer::draw_batches(const nqr_frame& frame, const FrameView& view, BrushModelGpu& model,
                               const SurfaceBatches& batches, const glm::mat4& model_matrix,
                               float alpha) {
    // Brush polygons arrive counter-clockwise seen from their front (the ABI's winding): cull
    // their backs, as GLQuake did.
    glEnable(GL_CULL_FACE);
    glFrontFace(GL_CCW);
    glCullFace(GL_BACK);
    const bool translucent = alpha < 1.0f;
    if (translucent) {
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glDepthMask(GL_FALSE);
    }
    glBindVertexArray(model.vertex_array());
    bind_texture(kUnitLightmap, GL_TEXTURE_2D_ARRAY, model.lightmap_texture());

    gl::Program& lit = programs_.lit;
    set_common_uniforms(lit, view, model_matrix);
    glUniform1f(lit.location("u_overbright"), settings.overbright);
    glUniform1f(lit.location("u_alpha"), alpha);
    draw_kind(model, batches, SurfaceKind::lit, lit);

    gl::Program& sky = programs_.sky;
    set_common_uniforms(sky, view, model_matrix);
    glUniform3fv(sky.location("u_eye"), 1, glm::value_ptr(view.eye));
    glUniform2f(sky.location("u_scroll"),
                static_cast<float>(std::fmod(frame.time * kSkyBackSpeed, kSkyLayerSize)),
                static_cast<float>(std::fmod(frame.time * kSkyFrontSpeed, kSkyLayerSize)));
    glUniform1f(sky.location("u_alpha"), alpha);
    draw_kind(model, batches, SurfaceKind::sky, sky);

    const float water_alpha = alpha * std::clamp(settings.water_alpha, 0.0f, 1.0f);
    if (water_alpha < 1.0f && !translucent) {
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glDepthMask(GL_FALSE);
    }
    gl::Program& liquid = programs_.liquid;
    set_common_uniforms(liquid, view, model_matrix);
    glUniform1f(liquid.location("u_time"), static_cast<float>(std::fmod(frame.time, kTwoPi)));
    glUniform1f(liquid.location("u_alpha"), water_alpha);
    draw_kind(model, batches, SurfaceKind::liquid, liquid);

    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
}

void WorldDrawer::draw_selection(const nqr_frame& frame, const FrameView& view,
                                 BrushModelGpu& model, SurfaceSelection selection,
                                 const glm::mat4& model_matrix, bool alternate_animation,
                                 float alpha) {
    const SurfaceBatches& batches = model.batch(selection, frame.time, alternate_animation);
    draw_batches(frame, view, model, batches, model_matrix, alpha);
}

const RegisteredModel* WorldDrawer::world_selection(const nqr_frame& frame,
                                                    const ModelRegistry& models,
                                                    SurfaceSelection& selection) {
    const RegisteredModel* world = models.find(frame.world);
    if (!world || !world->brush) return nullptr;
    if (frame.visible_surfaces) {
        selection = {frame.visible_surfaces, 0, frame.num_visible_surfaces};
    } else {
        selection = {nullptr, world->first_surface, world->num_surfaces};
    }
    return world;
}

template <typename Visit>
void WorldDrawer::for_each_brush_entity(const nqr_frame& frame, const ModelRegistry& models,
                                        Visit&& visit) {
    if (!frame.brush_entities) return;
    for (uint32_t i = 0; i < frame.num_brush_entities; ++i) {
        const nqr_entity* entity = frame.brush_entities[i];
        if (!entity_in_view(entity)) continue;
        const RegisteredModel* model = models.find(entity->model);
        if (!model || !model->brush) continue;
        visit(*entity, *model,
              SurfaceSelection{nullptr, model->first_surface, model->num_surfaces});
    }
}

void WorldDrawer::prepare_lightmaps(const nqr_frame& frame, const ModelRegistry& models,
                                    bool with_world) {
    SurfaceSelection selection;
    const RegisteredModel* world = with_world ? world_selection(frame, models, selection) : nullptr;
    if (world) {
        world->brush->rebuild_lightmaps(selection, frame.lightstyles,
                                        gather_lights(frame, glm::mat4(1.0f)));
    }
    auto rebuild = [&](const nqr_entity& entity, const RegisteredModel& model,
                       SurfaceSelection surfaces) {
        model.brush->rebuild_lightmaps(surfaces, frame.lightstyles,
                                       gather_lights(frame, mat4_from(entity.model_matrix)));
    };
    for_each_brush_entity(frame, models, rebuild);
    // Every rebuild before the first upload: a model's atlas then changes texture once a frame.
    if (world) world->brush->upload_lightmaps();
    for_each_brush_entity(frame, models,
                          [](const nqr_entity&, const RegisteredModel& model, SurfaceSelection) {
                              model.brush->upload_lightmaps();
                          });
}

void WorldDrawer::draw_world(const nqr_frame& frame, const ModelRegistry& models) {
    FrameView view;
    if (!read_frame_view(&frame, view)) return;
    SurfaceSelection selection;
    const RegisteredModel* world = world_selection(frame, models, selection);
    if (!world) return;
    prepare_lightmaps(frame, models, true);
    entities_prepared_for_ = frame.number;
    entities_prepared_ = true;
    begin_classic_pass();
    draw_selection(frame, view, *world->brush, selection, glm::mat4(1.0f), false, 1.0f);
    end_classic_pass();
}

void WorldDrawer::draw_brush_entities(const nqr_frame& frame, const ModelRegistry& models) {
    FrameView view;
    if (!read_frame_view(&frame, view) || !frame.brush_entities) return;
    if (!entities_prepared_ || entities_prepared_for_ != frame.number) {
        prepare_lightmaps(frame, models, false);  // no world pass ran before this one
    }
    entities_prepared_ = false;
    begin_classic_pass();
    for_each_brush_entity(
        frame, models,
        [&](const nqr_entity& entity, const RegisteredModel& model, SurfaceSelection selection) {
            draw_selection(frame, view, *model.brush, selection, mat4_from(entity.model_matrix),
                           entity.frame != 0, entity_alpha(entity.alpha));
        });
    end_classic_pass();
}

}  // namespace nq::npr::classic
