// Draws sprite entities as GLQuake did: an unlit quad spanned by the sprite type's axes
// (sprite_orientation.h), the image of the entity's pose0 (the engine resolves frame groups),
// alpha-tested at 0.666 so palette index 255 shows what is behind. Entity alpha < 1 blends.
#pragma once

#include <cstdint>
#include <string>

#include "abi/frame_view.h"
#include "classic/model_registry.h"
#include "gl/program.h"
#include "nqr_renderer.h"

namespace nq::npr::classic {

class SpriteDrawer {
  public:
    bool init(gl::ObjectTracker* tracker, std::string& error);
    void reset();

    void draw_sprite_entities(const nqr_frame& frame, const ModelRegistry& models);
    void draw_entity(const FrameView& view, const nqr_entity& entity, const SpriteModelGpu& model);

  private:
    gl::Program program_;
    gl::VertexArray empty_vertex_array_;  // core profile draws need one bound
};

}  // namespace nq::npr::classic
