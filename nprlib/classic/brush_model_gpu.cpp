#include "classic/brush_model_gpu.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cstddef>

#include "abi/abi_access.h"
#include "classic/texture_animation.h"

namespace nq::npr::classic {
namespace {

bool validate(const nqr_brush_model& brush, std::string& error) {
    if (!has_known_prefix(&brush)) {
        error = "brush model struct is smaller than this nprlib expects";
    } else if (!abi_array_usable(brush.surfaces, brush.num_surfaces)) {
        error = "brush model surfaces missing or of an unknown size";
    } else if (!abi_array_usable(brush.textures, brush.num_textures)) {
        error = "brush model textures missing or of an unknown size";
    } else if (brush.num_vertices > 0 && brush.positions == nullptr) {
        error = "brush model has vertices but no positions";
    }
    return error.empty();
}

// Small models (b_*.bsp item boxes, test rooms) get small pages instead of a 1 MB one.
int choose_lightmap_page_size(const nqr_brush_model& brush) {
    long area = 0;
    int largest = 0;
    for (uint32_t i = 0; i < brush.num_surfaces; ++i) {
        const nqr_surface& surface = abi_element(brush.surfaces, i);
        if (!surface_is_lightmapped(brush, surface)) continue;
        const SurfaceLightmapSize size = surface_lightmap_size(surface);
        area += static_cast<long>(size.width) * size.height;
        largest = std::max({largest, size.width, size.height});
    }
    for (int page : {128, 256}) {
        if (largest <= page && area * 5 / 4 <= static_cast<long>(page) * page) return page;
    }
    return kLightmapPageSize;
}

void set_float_attribute(GLuint location, GLint components, size_t offset) {
    glEnableVertexAttribArray(location);
    glVertexAttribPointer(location, components, GL_FLOAT, GL_FALSE, sizeof(BrushVertex),
                          reinterpret_cast<const void*>(offset));
}

}  // namespace

std::unique_ptr<BrushModelGpu> BrushModelGpu::create(gl::ObjectTracker* tracker,
                                                     const nqr_brush_model& brush,
                                                     const uint8_t* palette_rgb, std::string& error,
                                                     const gl::RgbaFilter* texture_filter) {
    if (!validate(brush, error)) return nullptr;
    std::unique_ptr<BrushModelGpu> model(new BrushModelGpu());
    model->brush_ = &brush;
    const int page_size = choose_lightmap_page_size(brush);
    BrushMesh mesh = build_brush_mesh(brush, page_size);
    model->upload_geometry(tracker, mesh);
    model->textures_ = create_brush_textures(tracker, brush, palette_rgb, texture_filter);
    model->atlas_.create(tracker, page_size, mesh.lightmap_pages);
    model->light_.assign(brush.num_surfaces, SurfaceLight{});
    model->accumulator_.assign(static_cast<size_t>(mesh.largest_lightmap_samples) * 3, 0.0f);
    model->batches_.resize(brush.num_surfaces, model->textures_.size());
    model->surfaces_ = std::move(mesh.surfaces);
    return model;
}

void BrushModelGpu::upload_geometry(gl::ObjectTracker* tracker, const BrushMesh& mesh) {
    vertex_array_ = gl::VertexArray::create(tracker);
    vertices_ = gl::Buffer::create(tracker);
    indices_ = gl::Buffer::create(tracker);
    glBindVertexArray(vertex_array_.id());
    glBindBuffer(GL_ARRAY_BUFFER, vertices_.id());
    glBufferData(GL_ARRAY_BUFFER,
                 static_cast<GLsizeiptr>(mesh.vertices.size() * sizeof(BrushVertex)),
                 mesh.vertices.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.id());
    glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                 static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(uint32_t)),
                 mesh.indices.data(), GL_STATIC_DRAW);
    set_float_attribute(0, 3, offsetof(BrushVertex, position));
    set_float_attribute(1, 2, offsetof(BrushVertex, texel));
    set_float_attribute(2, 3, offsetof(BrushVertex, lightmap));
    set_float_attribute(3, 3, offsetof(BrushVertex, normal));
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

bool BrushModelGpu::surface_needs_rebuild(uint32_t surface, const float* lightstyles,
                                          bool lit_dynamically, float* styles_out) const {
    const nqr_surface& source = abi_element(brush_->surfaces, surface);
    const SurfaceLight& state = light_[surface];
    bool changed = !state.built || lit_dynamically || state.dynamic;
    const int styles = count_styles(source);
    for (int i = 0; i < kMaxLightStyles; ++i) {
        styles_out[i] = i < styles ? frame_style_value(lightstyles, source.styles[i]) : 0.0f;
        changed = changed || styles_out[i] != state.applied_styles[i];
    }
    return changed;
}

void BrushModelGpu::rebuild_surface(uint32_t surface, const float* styles,
                                    std::span<const DynamicLight> lights, bool lit_dynamically) {
    const BrushSurfaceMesh& mesh = surfaces_[surface];
    SurfaceLightInput input;
    input.surface = &abi_element(brush_->surfaces, surface);
    input.lighting_rgb = brush_->lighting_rgb;
    input.num_light_samples = brush_->num_light_samples;
    for (int i = 0; i < kMaxLightStyles; ++i) input.style_values[i] = styles[i];
    if (lit_dynamically) input.dynamic_lights = lights;
    build_surface_lightmap(input, accumulator_.data(),
                           atlas_.texel(mesh.lightmap_page, mesh.lightmap_x, mesh.lightmap_y),
                           atlas_.row_bytes());
    atlas_.mark_dirty(mesh.lightmap_page, mesh.lightmap_x, mesh.lightmap_y,
                      mesh.lightmap_size.width, mesh.lightmap_size.height);
    SurfaceLight& state = light_[surface];
    for (int i = 0; i < kMaxLightStyles; ++i) state.applied_styles[i] = styles[i];
    state.built = true;
    state.dynamic = lit_dynamically;
    ++lightmap_rebuilds_;
}

void BrushModelGpu::rebuild_lightmaps(SurfaceSelection selection, const float* lightstyles,
                                      std::span<const DynamicLight> lights) {
    for (uint32_t i = 0; i < selection.count; ++i) {
        const uint32_t surface = selection.at(i);
        if (surface >= surfaces_.size() || surfaces_[surface].lightmap_page < 0) continue;
        const nqr_surface& source = abi_element(brush_->surfaces, surface);
        bool lit_dynamically = false;
        for (const DynamicLight& light : lights) {
            lit_dynamically = lit_dynamically || dynamic_light_reaches(source, light);
        }
        float styles[kMaxLightStyles];
        if (surface_needs_rebuild(surface, lightstyles, lit_dynamically, styles)) {
            rebuild_surface(surface, styles, lights, lit_dynamically);
        }
    }
}

uint32_t BrushModelGpu::texture_slot_for(const nqr_surface& surface, double time,
                                         bool alternate) const {
    const auto placeholder = static_cast<uint32_t>(textures_.size() - 1);
    const int32_t resolved = animated_texture(*brush_, surface.texture, time, alternate);
    if (resolved < 0 || static_cast<uint32_t>(resolved) >= placeholder) return placeholder;
    return static_cast<uint32_t>(resolved);
}

const SurfaceBatches& BrushModelGpu::batch(SurfaceSelection selection, double time,
                                           bool alternate) {
    batches_.begin();
    for (uint32_t i = 0; i < selection.count; ++i) {
        const uint32_t surface = selection.at(i);
        if (surface >= surfaces_.size()) continue;
        const nqr_surface& source = abi_element(brush_->surfaces, surface);
        batches_.add(surface, texture_slot_for(source, time, alternate));
    }
    batches_.finish(surfaces_);
    return batches_;
}

}  // namespace nq::npr::classic
