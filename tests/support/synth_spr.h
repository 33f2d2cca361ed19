// Writers for synthetic sprites (IDSP v1): test fixtures and fuzz seeds. Counts can be
// overridden so tests can build each malformed case.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "support/seed_file.h"

namespace nq::test {

struct SynthSpr {
    struct Picture {
        int32_t origin_x = 0, origin_y = 0;
        int32_t width = 0, height = 0;
        std::vector<uint8_t> pixels;  // written as given (may disagree with width * height)
    };
    struct Frame {
        int32_t type = 0;                    // 0 single, 1 group
        std::optional<int32_t> group_count;  // overrides pictures.size() in a group
        std::vector<float> intervals;        // group only
        std::vector<Picture> pictures;       // one for a single frame
    };

    std::string ident = "IDSP";
    int32_t version = 1;
    int32_t type = 2;  // vp_parallel
    float bounding_radius = 8;
    int32_t max_width = 4;
    int32_t max_height = 4;
    std::optional<int32_t> num_frames;  // unset: frames.size()
    float beam_length = 0;
    int32_t sync_type = 0;
    std::vector<Frame> frames;
    std::vector<uint8_t> trailing;
};

std::vector<uint8_t> write_spr(const SynthSpr& spr);

// A w x h picture centred on the origin, pixels counting up from `first`.
SynthSpr::Picture synth_picture(int32_t width, int32_t height, uint8_t first);
// One single 4x4 frame. Valid.
SynthSpr minimal_spr();
// A single 4x4 frame then a group of two pictures (4x2, 2x4) with intervals. Valid.
SynthSpr animated_spr();

std::vector<SeedFile> synthetic_spr_seeds();

}  // namespace nq::test
