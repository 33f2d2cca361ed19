#include "classic/alias_model_gpu.h"

#include <epoxy/gl.h>

#include <cstddef>
#include <span>

#include "abi/abi_access.h"
#include "classic/alias_mesh.h"
#include "gl/texture_upload.h"

namespace nq::npr::classic {

std::unique_ptr<AliasModelGpu> AliasModelGpu::create(gl::ObjectTracker* tracker,
                                                     const nqr_alias_model& model,
                                                     const uint8_t* palette_rgb,
                                                     std::string& error) {
    if (!validate_alias_model(model, error)) return nullptr;
    std::unique_ptr<AliasModelGpu> gpu(new AliasModelGpu());
    gpu->model_ = &model;
    AliasMesh mesh = build_alias_mesh(model);
    if (!gpu->upload_poses(tracker, mesh.pose_texels, error)) return nullptr;
    gpu->pose_texels_ = std::move(mesh.pose_texels);

    gpu->vertex_array_ = gl::VertexArray::create(tracker);
    gpu->vertices_ = gl::Buffer::create(tracker);
    gpu->indices_ = gl::Buffer::create(tracker);
    glBindVertexArray(gpu->vertex_array_.id());
    glBindBuffer(GL_ARRAY_BUFFER, gpu->vertices_.id());
    glBufferData(GL_ARRAY_BUFFER,
                 static_cast<GLsizeiptr>(mesh.vertices.size() * sizeof(AliasMeshVertex)),
                 mesh.vertices.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gpu->indices_.id());
    glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                 static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(uint32_t)),
                 mesh.indices.data(), GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribIPointer(0, 1, GL_UNSIGNED_INT, sizeof(AliasMeshVertex),
                           reinterpret_cast<const void*>(offsetof(AliasMeshVertex, pose_vertex)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, sizeof(AliasMeshVertex),
                          reinterpret_cast<const void*>(offsetof(AliasMeshVertex, uv)));
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    gpu->index_count_ = static_cast<GLsizei>(mesh.indices.size());
    gpu->upload_skins(tracker, palette_rgb);
    return gpu;
}

bool AliasModelGpu::upload_poses(gl::ObjectTracker* tracker, const std::vector<uint8_t>& texels,
                                 std::string& error) {
    GLint max_texels = 0;
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &max_texels);
    const size_t count = texels.size() / 4;
    if (count > static_cast<size_t>(max_texels)) {
        error = "alias model poses need " + std::to_string(count) +
                " buffer texels, the GL allows " + std::to_string(max_texels);
        return false;
    }
    poses_ = gl::Buffer::create(tracker);
    glBindBuffer(GL_TEXTURE_BUFFER, poses_.id());
    glBufferData(GL_TEXTURE_BUFFER, static_cast<GLsizeiptr>(texels.size()), texels.data(),
                 GL_STATIC_DRAW);
    glBindBuffer(GL_TEXTURE_BUFFER, 0);
    pose_texture_ = gl::Texture::create(tracker);
    glBindTexture(GL_TEXTURE_BUFFER, pose_texture_.id());
    glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA8UI, poses_.id());
    glBindTexture(GL_TEXTURE_BUFFER, 0);
    return true;
}

void AliasModelGpu::upload_skins(gl::ObjectTracker* tracker, const uint8_t* palette_rgb) {
    const nqr_alias_model& model = *model_;
    const size_t pixels = static_cast<size_t>(model.skin_width) * model.skin_height;
    gl::PaletteExpansion expansion{.blacken_fullbrights = true};
    if (holey()) expansion.transparent = gl::Transparent::index255;
    std::vector<uint8_t> scratch;
    skins_.resize(model.num_skins);
    for (uint32_t s = 0; s < model.num_skins; ++s) {
        const nqr_alias_skin& skin = abi_element(model.skins, s);
        for (uint32_t i = 0; skin.images && i < skin.num_images; ++i) {
            if (!skin.images[i]) continue;
            std::span<const uint8_t> image(skin.images[i], pixels);
            SkinImageGpu gpu;
            gpu.base =
                gl::create_palette_texture(tracker, model.skin_width, model.skin_height, image,
                                           palette_rgb, expansion, gl::kMipmappedRepeat, scratch);
            gpu.fullbright =
                gl::create_fullbright_texture(tracker, model.skin_width, model.skin_height, image,
                                              palette_rgb, gl::kMipmappedRepeat, scratch);
            skins_[s].push_back(std::move(gpu));
        }
    }
}

bool AliasModelGpu::locate(uint32_t& skin, uint32_t& image) const {
    if (skins_.empty()) return false;
    if (skin >= skins_.size()) skin = 0;
    if (skins_[skin].empty()) return false;
    if (image >= skins_[skin].size()) image = 0;
    return true;
}

const SkinImageGpu* AliasModelGpu::skin_image(uint32_t skin, uint32_t image) const {
    if (!locate(skin, image)) return nullptr;
    return &skins_[skin][image];
}

const uint8_t* AliasModelGpu::skin_pixels(uint32_t skin, uint32_t image) const {
    if (!locate(skin, image)) return nullptr;
    const nqr_alias_skin& source = abi_element(model_->skins, skin);
    // Images without pixels were skipped when uploading; count the ones that had them.
    uint32_t present = 0;
    for (uint32_t i = 0; i < source.num_images; ++i) {
        if (!source.images[i]) continue;
        if (present == image) return source.images[i];
        ++present;
    }
    return nullptr;
}

}  // namespace nq::npr::classic
