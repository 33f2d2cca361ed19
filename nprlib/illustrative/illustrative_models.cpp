#include "illustrative/illustrative_models.h"

#include <epoxy/gl.h>

#include <span>

#include "abi/abi_access.h"
#include "classic/alias_mesh.h"
#include "classic/player_colors.h"
#include "gl/texture_upload.h"
#include "illustrative/skin_masks.h"
#include "illustrative/smooth_normals.h"

namespace nq::npr::illustrative {
namespace {

bool is_team_colour_index(uint8_t index) {
    const auto in_range = [&](int start) {
        return index >= start && index < start + classic::kColourRangeLength;
    };
    return in_range(classic::kShirtRangeStart) || in_range(classic::kPantsRangeStart);
}

// Smooth normals come per shading vertex of the smoothing layout, whose corners follow the
// valid triangles in model order: a corner's slot is its shading vertex.
CornerNormals corner_normals_from(const nqr_alias_model& model, const AliasSmoothNormals& smooth) {
    CornerNormals out;
    out.num_slots = smooth.layout.num_vertices();
    out.normals = smooth.normals;
    out.corner_slots.assign(static_cast<size_t>(model.num_triangles) * 3, 0);
    size_t corner = 0;
    for (uint32_t t = 0; t < model.num_triangles; ++t) {
        const int32_t* triangle = model.triangles + static_cast<size_t>(t) * 4;
        if (!classic::alias_triangle_valid(model, triangle)) continue;
        for (int c = 0; c < 3 && corner < smooth.layout.indices.size(); ++c, ++corner) {
            out.corner_slots[static_cast<size_t>(t) * 3 + c] = smooth.layout.indices[corner];
        }
    }
    return out;
}

std::vector<uint8_t> skin_mask_texels(std::span<const uint8_t> pixels, int width, int height,
                                      const PaletteMasks& palette_masks) {
    std::vector<uint8_t> rgba = derive_skin_masks(pixels, width, height, palette_masks);
    for (size_t i = 0; i < pixels.size() && i * 4 + 3 < rgba.size(); ++i) {
        rgba[i * 4 + 3] = is_team_colour_index(pixels[i]) ? 255 : 0;
    }
    return rgba;
}

}  // namespace

GLuint IllustrativeModelData::masks_for(uint32_t skin, uint32_t image) const {
    if (masks.empty()) return 0;
    const auto& images = masks[std::min<size_t>(skin, masks.size() - 1)];
    if (images.empty()) return 0;
    return images[std::min<size_t>(image, images.size() - 1)].id();
}

void IllustrativeModels::init(gl::ObjectTracker* tracker, const uint8_t* palette,
                              FileReader read_file, Logger log) {
    tracker_ = tracker;
    palette_ = palette;
    read_file_ = std::move(read_file);
    log_ = std::move(log);
    models_.clear();
}

CornerNormals IllustrativeModels::normals_for(const nqr_alias_model& model,
                                              const ModelLoadOptions& options) const {
    if (!options.smooth_normals) return mdl_vertex_normals(model);
    const classic::AliasMesh mesh = classic::build_alias_mesh(model);
    const AliasSmoothNormals smooth =
        compute_alias_smooth_normals(model, mesh, options.crease_angle_degrees);
    if (!smooth.layout.error.empty()) {
        log_(NQR_LOG_WARNING, "illustrative: smooth normals: " + smooth.layout.error +
                                  "; using the model's vertex normals");
        return mdl_vertex_normals(model);
    }
    return corner_normals_from(model, smooth);
}

void IllustrativeModels::add(const nqr_model& model, const ModelLoadOptions& options) {
    models_.erase(model.id);
    if (model.kind != NQR_MODEL_ALIAS || !model.alias) return;
    const nqr_alias_model& alias = *model.alias;
    std::string error;
    if (!classic::validate_alias_model(alias, error)) return;  // classic logs it
    IllustrativeModelData data;
    data.mesh = IllustrativeModel::create(tracker_, alias, normals_for(alias, options), error);
    if (!data.mesh) {
        log_(NQR_LOG_WARNING,
             std::string("illustrative: ") + (model.name ? model.name : "?") + ": " + error);
        return;
    }
    const PaletteMasks palette_masks = derive_palette_masks(palette_);
    const size_t pixels = static_cast<size_t>(alias.skin_width) * alias.skin_height;
    data.masks.resize(alias.num_skins);
    for (uint32_t s = 0; s < alias.num_skins; ++s) {
        const nqr_alias_skin& skin = npr::abi_element(alias.skins, s);
        for (uint32_t i = 0; i < skin.num_images; ++i) {
            if (!skin.images || !skin.images[i]) {
                data.masks[s].emplace_back();  // drawn with neutral masks
                continue;
            }
            const std::vector<uint8_t> rgba = skin_mask_texels(
                {skin.images[i], pixels}, alias.skin_width, alias.skin_height, palette_masks);
            data.masks[s].push_back(gl::create_rgba8_texture(
                tracker_, alias.skin_width, alias.skin_height, rgba, gl::kNearestRepeat));
        }
    }
    if (model.name) load_material(model.name, data);
    models_[model.id] = std::move(data);
}

void IllustrativeModels::load_material(const std::string& model_name,
                                       IllustrativeModelData& out) const {
    const std::string path = model_name + ".mat";
    const std::optional<std::vector<uint8_t>> bytes = read_file_ ? read_file_(path) : std::nullopt;
    if (!bytes) return;  // no material file: the style's defaults
    const MaterialParseResult parsed = parse_material_file(*bytes, path);
    for (const MaterialWarning& warning : parsed.warnings) {
        log_(NQR_LOG_WARNING, "illustrative: " + format_material_warning(path, warning));
    }
    if (!parsed.ok()) {
        log_(NQR_LOG_WARNING, "illustrative: " + parsed.error + "; using the defaults");
        return;
    }
    out.material = parsed.material;
    if (!out.material.light_warp_texture) return;
    const WarpRampResult ramp =
        find_warp_ramp(*out.material.light_warp_texture, read_file_, palette_);
    if (!ramp.ramp) {
        log_(NQR_LOG_WARNING, "illustrative: " + path + ": $lightwarptexture: " + ramp.error +
                                  "; using the style's ramp");
        return;
    }
    out.warp = create_warp_texture(tracker_, *ramp.ramp);
}

void IllustrativeModels::remove(nqr_model_id id) {
    models_.erase(id);
}

const IllustrativeModelData* IllustrativeModels::find(nqr_model_id id) const {
    const auto it = models_.find(id);
    return it == models_.end() ? nullptr : &it->second;
}

MaterialParams apply_overrides(const MaterialParams& defaults, const MaterialOverrides& overrides) {
    MaterialParams out = defaults;
    if (overrides.phong_exponent) {
        out.phong_exponent = *overrides.phong_exponent;
        out.exponent_from_skin = false;  // Source: a constant exponent replaces the mask's
    }
    if (overrides.phong_boost) out.phong_boost = *overrides.phong_boost;
    if (overrides.phong_fresnel_ranges) {
        for (int i = 0; i < 3; ++i) out.fresnel_ranges[i] = (*overrides.phong_fresnel_ranges)[i];
    }
    if (overrides.rim_light) out.rim_light = *overrides.rim_light;
    if (overrides.rim_light_exponent) out.rim_exponent = *overrides.rim_light_exponent;
    if (overrides.rim_light_boost) out.rim_boost = *overrides.rim_light_boost;
    if (overrides.rim_mask) out.rim_mask = *overrides.rim_mask;
    if (overrides.ambient_scale) out.ambient_scale = *overrides.ambient_scale;
    if (overrides.self_illum) out.self_illum = *overrides.self_illum;
    return out;
}

gl::Texture create_warp_texture(gl::ObjectTracker* tracker, const WarpRamp& ramp) {
    const std::vector<uint8_t> rgb = ramp.to_rgb8();
    std::vector<uint8_t> rgba(kWarpRampSize * 4, 255);
    for (int i = 0; i < kWarpRampSize; ++i) {
        for (int c = 0; c < 3; ++c) rgba[i * 4 + c] = rgb[static_cast<size_t>(i) * 3 + c];
    }
    return gl::create_rgba8_texture(tracker, kWarpRampSize, 1, rgba, gl::kLinearClamp);
}

}  // namespace nq::npr::illustrative
