// Player-coloured skins, made once per (model, skin image, top, bottom) and kept in a small
// least-recently-used cache: the translated palette image is uploaded as an ordinary mipmapped
// texture, so colours are exact palette colours and filtering works as for any skin. A cache
// hit costs a short scan and allocates nothing; only a new colour combination uploads.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "classic/alias_model_gpu.h"
#include "gl/handles.h"
#include "nqr_renderer.h"

namespace nq::npr::classic {

class TranslatedSkins {
  public:
    static constexpr size_t kCapacity = 32;  // 16 players + spare

    void init(gl::ObjectTracker* tracker, const uint8_t* palette_rgb);
    void reset();

    // The translated base texture for this entity's skin, or 0 when the model has no skin.
    GLuint get(nqr_model_id model_id, const AliasModelGpu& model, uint32_t skin, uint32_t image,
               uint8_t top, uint8_t bottom, uint64_t frame_number);

    void forget_model(nqr_model_id model_id);
    int uploads() const { return uploads_; }  // textures made so far (tests)

  private:
    struct Entry {
        nqr_model_id model = 0;
        uint32_t skin = 0, image = 0;
        uint8_t top = 0, bottom = 0;
        uint64_t last_used = 0;
        gl::Texture texture;
    };

    Entry& victim();

    gl::ObjectTracker* tracker_ = nullptr;
    const uint8_t* palette_ = nullptr;
    std::array<Entry, kCapacity> entries_;
    std::vector<uint8_t> translated_, rgba_;
    int uploads_ = 0;
};

}  // namespace nq::npr::classic
