// Writers for synthetic alias models (IDPO v6): test fixtures and fuzz seeds. Every field is
// explicit, and the header counts can be overridden, so tests can build each malformed case.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "support/seed_file.h"

namespace nq::test {

// Little-endian byte building for the synthetic writers (also used by synth_spr and synth_wad).
class LeWriter {
  public:
    void i32(int32_t v) { u32(static_cast<uint32_t>(v)); }
    void u32(uint32_t v);
    void f32(float v);
    void u8(uint8_t v) { out_.push_back(v); }
    void bytes(const std::vector<uint8_t>& b) { out_.insert(out_.end(), b.begin(), b.end()); }
    void text(std::string_view s) { out_.insert(out_.end(), s.begin(), s.end()); }
    // `s` NUL-padded (or cut) to exactly `width` bytes.
    void fixed_string(std::string_view s, size_t width);
    size_t size() const { return out_.size(); }
    std::vector<uint8_t> take() { return std::move(out_); }

  private:
    std::vector<uint8_t> out_;
};

struct SynthMdl {
    struct Skin {
        int32_t type = 0;                    // 0 single, 1 group; anything else to test rejection
        std::optional<int32_t> group_count;  // overrides images.size() in a group
        std::vector<float> intervals;        // group only
        std::vector<std::vector<uint8_t>> images;
    };
    struct TexCoord {
        int32_t on_seam = 0, s = 0, t = 0;
    };
    struct Triangle {
        int32_t faces_front = 1;
        std::array<int32_t, 3> vertices{};
    };
    struct Vertex {
        uint8_t x = 0, y = 0, z = 0, normal = 0;
    };
    struct Pose {
        Vertex bbox_min, bbox_max;
        std::string name;
        std::vector<Vertex> vertices;
    };
    struct Frame {
        int32_t type = 0;                    // 0 single, 1 group
        std::optional<int32_t> group_count;  // overrides poses.size() in a group
        Vertex group_bbox_min, group_bbox_max;
        std::vector<float> intervals;  // group only
        std::vector<Pose> poses;       // one for a single frame
    };

    std::string ident = "IDPO";
    int32_t version = 6;
    std::array<float, 3> scale{0.5f, 0.25f, 1.0f};
    std::array<float, 3> scale_origin{-8.0f, -4.0f, 0.0f};
    float bounding_radius = 16;
    std::array<float, 3> eye_position{0, 0, 24};
    int32_t skin_width = 8;
    int32_t skin_height = 4;
    int32_t sync_type = 0;
    int32_t flags = 0;
    float size = 2;
    // Header counts; unset means "the size of the matching vector".
    std::optional<int32_t> num_skins, num_verts, num_tris, num_frames;

    std::vector<Skin> skins;
    std::vector<TexCoord> tex_coords;
    std::vector<Triangle> triangles;
    std::vector<Frame> frames;
    std::vector<uint8_t> trailing;  // appended after the last frame
};

std::vector<uint8_t> write_mdl(const SynthMdl& mdl);

// One 8x4 skin, 4 vertices, 2 triangles, one single frame "base". Valid.
SynthMdl minimal_mdl();
// A skin group (2 images), a single frame "stand1" and a frame group "run" of 3 poses, flags
// rotate|tracer. Valid.
SynthMdl animated_mdl();

// Valid and malformed models for fuzzing.
std::vector<SeedFile> synthetic_mdl_seeds();

}  // namespace nq::test
