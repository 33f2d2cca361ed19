// Quake sprites ("IDSP", version 1): a 36-byte header and frames that are single pictures
// (origin, width, height, palette indices) or animated groups of pictures with intervals.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "common/result.h"

namespace nq {

inline constexpr int32_t kSprVersion = 1;
inline constexpr size_t kSprHeaderBytes = 36;

// How a sprite is oriented towards the viewer.
enum class SpriteType : int32_t {
    ViewParallelUpright = 0,
    FacingUpright = 1,
    ViewParallel = 2,
    Oriented = 3,
    ViewParallelOriented = 4,
};
const char* sprite_type_name(int32_t type);  // "vp_parallel_upright", ... or "unknown"

struct SprHeader {
    int32_t version = 0;
    int32_t type = 0;  // a SpriteType (validated)
    float bounding_radius = 0;
    int32_t max_width = 0;
    int32_t max_height = 0;
    int32_t num_frames = 0;
    float beam_length = 0;
    int32_t sync_type = 0;  // 0 = in sync, 1 = random start
};

struct SprPicture {
    int32_t origin_x = 0;  // offset of the picture's top-left corner from the sprite origin
    int32_t origin_y = 0;
    int32_t width = 0;
    int32_t height = 0;
    std::vector<uint8_t> pixels;  // width * height palette indices (255 = transparent)
};

// A frame: one picture, or an animated group of pictures with cumulative intervals.
struct SprFrame {
    bool is_group = false;
    std::vector<float> intervals;  // group only, one per picture
    std::vector<SprPicture> pictures;
};

struct Spr {
    SprHeader header;
    std::vector<SprFrame> frames;
    uint64_t trailing_bytes = 0;
    std::vector<std::string> warnings;
};

Result<Spr> parse_spr(std::span<const uint8_t> data, const std::string& name);

}  // namespace nq
