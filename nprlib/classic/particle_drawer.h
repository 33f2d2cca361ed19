// Draws particles as GLQuake did: small round dots in their palette colour, facing the camera,
// alpha-blended, not writing depth. GLQuake grew a particle with its distance d along the view
// direction (scale 1 closer than 20 units, else 1 + 0.004 d) so far ones stay visible; its dot
// was about one unit across at scale 1, so each is a camera-facing quad of side
// kParticleSize x scale with a disc cut out (soft edge). Particle data streams through a ring
// buffer, instanced, without per-frame allocation.
#pragma once

#include <cstdint>
#include <string>

#include "gl/program.h"
#include "gl/stream_buffer.h"
#include "nqr_renderer.h"

namespace nq::npr::classic {

inline constexpr float kParticleSize = 1.0f;

class ParticleDrawer {
  public:
    bool init(gl::ObjectTracker* tracker, const uint8_t* palette_rgb, std::string& error,
              gl::StreamBuffer::Mode mode = gl::StreamBuffer::Mode::automatic);
    void reset();

    void draw_particles(const nqr_frame& frame);

    const gl::StreamBuffer& stream() const { return stream_; }

  private:
    struct Instance {
        float origin[3];
        uint8_t rgba[4];
    };
    static_assert(sizeof(Instance) == 16);

    void draw_chunk(const nqr_frame& frame, uint32_t first, uint32_t count);

    const uint8_t* palette_ = nullptr;
    gl::Program program_;
    gl::VertexArray vertex_array_;
    gl::StreamBuffer stream_;
};

}  // namespace nq::npr::classic
