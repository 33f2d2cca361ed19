// What the illustrative style keeps per alias model, made once at registration: the mesh with
// smooth crease-preserving normals (smooth_normals.h), every skin image's masks (skin_masks.h:
// k_s, k_spec, k_r; alpha marks the shirt and pants texels player colours translate), and the
// model's material file (`<model>.mat`, material_file.h) with the warp ramp it names. Problems
// in a material file or ramp are logged with the file's name and the defaults are used.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "gl/handles.h"
#include "illustrative/illustrative_model.h"
#include "illustrative/illustrative_settings.h"
#include "illustrative/material_file.h"
#include "illustrative/warp_ramp.h"
#include "nqr_renderer.h"

namespace nq::npr::illustrative {

struct IllustrativeModelData {
    std::unique_ptr<IllustrativeModel> mesh;
    std::vector<std::vector<gl::Texture>> masks;  // [skin][image]
    MaterialOverrides material;
    gl::Texture warp;  // the material's own ramp; empty: the style's

    GLuint masks_for(uint32_t skin, uint32_t image) const;
};

// Model-independent inputs of registration.
struct ModelLoadOptions {
    bool smooth_normals = true;
    float crease_angle_degrees = 60.0f;
};

using FileReader = RampFileReader;  // path -> bytes, nullopt when missing
using Logger = std::function<void(int level, const std::string& text)>;

class IllustrativeModels {
  public:
    void init(gl::ObjectTracker* tracker, const uint8_t* palette, FileReader read_file,
              Logger log);
    // Alias models only; anything else is ignored. Registering an id again replaces it.
    void add(const nqr_model& model, const ModelLoadOptions& options);
    void remove(nqr_model_id id);
    void clear() { models_.clear(); }
    const IllustrativeModelData* find(nqr_model_id id) const;

  private:
    CornerNormals normals_for(const nqr_alias_model& model, const ModelLoadOptions& options) const;
    void load_material(const std::string& model_name, IllustrativeModelData& out) const;

    gl::ObjectTracker* tracker_ = nullptr;
    const uint8_t* palette_ = nullptr;
    FileReader read_file_;
    Logger log_;
    std::unordered_map<nqr_model_id, IllustrativeModelData> models_;
};

// The style's MaterialParams with a model's overrides on top.
MaterialParams apply_overrides(const MaterialParams& defaults, const MaterialOverrides& overrides);

// A 256 x 1 linear, clamped texture of a ramp.
gl::Texture create_warp_texture(gl::ObjectTracker* tracker, const WarpRamp& ramp);

}  // namespace nq::npr::illustrative
