#include "formats/spr.h"

#include "common/byte_reader.h"
#include "formats/mdl.h"  // sprites share the alias-model interval and float rules

namespace nq {

namespace {

constexpr size_t kTypeOffset = 8;
constexpr size_t kNumFramesOffset = 24;
constexpr size_t kPictureHeaderBytes = 16;
constexpr size_t kMinFrameBytes = 4 + kPictureHeaderBytes;

struct Tally {
    size_t pictures_over_max = 0;
};

SprHeader read_header(ByteReader& in, std::vector<std::string>& warnings) {
    if (in.size() < kSprHeaderBytes) in.fail("file too small for a sprite header (36 bytes)");
    std::string ident(reinterpret_cast<const char*>(in.bytes(4).data()), 4);
    if (ident != "IDSP") in.fail_at(0, "not a sprite (identifier is not \"IDSP\")");
    SprHeader h;
    h.version = in.i32();
    if (h.version != kSprVersion) {
        in.fail_at(4, "unsupported sprite version " + std::to_string(h.version) + " (expected 1)");
    }
    h.type = in.i32();
    h.bounding_radius = read_informational_float(in, "bounding radius", warnings);
    h.max_width = in.i32();
    h.max_height = in.i32();
    h.num_frames = in.i32();
    h.beam_length = read_informational_float(in, "beam length", warnings);
    h.sync_type = in.i32();
    return h;
}

void validate_header(const ByteReader& in, const SprHeader& h, std::vector<std::string>& warn) {
    if (h.type < int32_t(SpriteType::ViewParallelUpright) ||
        h.type > int32_t(SpriteType::ViewParallelOriented)) {
        in.fail_at(kTypeOffset,
                   "unknown sprite type " + std::to_string(h.type) + " (expected 0..4)");
    }
    if (h.num_frames <= 0) {
        in.fail_at(kNumFramesOffset,
                   "frame count must be positive, header says " + std::to_string(h.num_frames));
    }
    const uint64_t available = in.size() - kSprHeaderBytes;
    if (uint64_t(h.num_frames) > available / kMinFrameBytes) {
        in.fail_at(kNumFramesOffset, "frame count " + std::to_string(h.num_frames) +
                                         " cannot fit in the " + std::to_string(available) +
                                         " bytes after the header");
    }
    if (h.max_width < 0 || h.max_height < 0) {
        warn.push_back("negative maximum size " + std::to_string(h.max_width) + "x" +
                       std::to_string(h.max_height));
    }
    if (h.sync_type != 0 && h.sync_type != 1) {
        warn.push_back("unknown sync type " + std::to_string(h.sync_type));
    }
}

int32_t read_picture_size(ByteReader& in, const std::string& owner, const char* what) {
    const size_t at = in.tell();
    const int32_t v = in.i32();
    if (v <= 0) in.fail_at(at, owner + " " + what + " must be positive, is " + std::to_string(v));
    return v;
}

SprPicture read_picture(ByteReader& in, const SprHeader& h, const std::string& owner,
                        Tally& tally) {
    SprPicture pic;
    pic.origin_x = in.i32();
    pic.origin_y = in.i32();
    pic.width = read_picture_size(in, owner, "width");
    pic.height = read_picture_size(in, owner, "height");
    const int64_t count = int64_t{pic.width} * pic.height;
    in.require_records(
        count, 1,
        owner + " pixels (" + std::to_string(pic.width) + "x" + std::to_string(pic.height) + ")");
    auto pixels = in.bytes(size_t(count));
    pic.pixels.assign(pixels.begin(), pixels.end());
    if (pic.width > h.max_width || pic.height > h.max_height) ++tally.pictures_over_max;
    return pic;
}

SprFrame read_frame(ByteReader& in, const SprHeader& h, size_t index, Tally& tally,
                    std::vector<std::string>& warnings) {
    const std::string owner = "frame " + std::to_string(index);
    const size_t type_at = in.tell();
    const int32_t type = in.i32();
    SprFrame frame;
    if (type == 0) {
        frame.pictures.push_back(read_picture(in, h, owner, tally));
        return frame;
    }
    if (type != 1) in.fail_at(type_at, owner + " has unknown type " + std::to_string(type));
    frame.is_group = true;
    const size_t count_at = in.tell();
    const int32_t count = in.i32();
    if (count <= 0) {
        in.fail_at(count_at, owner + " group count must be positive, is " + std::to_string(count));
    }
    in.require_records(count, 4 + kPictureHeaderBytes, owner + " group (interval + picture each)");
    frame.intervals = read_animation_intervals(in, count, owner, warnings);
    frame.pictures.reserve(size_t(count));
    for (int32_t i = 0; i < count; ++i) {
        frame.pictures.push_back(
            read_picture(in, h, owner + " picture " + std::to_string(i), tally));
    }
    return frame;
}

Spr parse_spr_body(std::span<const uint8_t> data, const std::string& name) {
    ByteReader in(data, name);
    Spr spr;
    spr.header = read_header(in, spr.warnings);
    validate_header(in, spr.header, spr.warnings);
    Tally tally;
    spr.frames.reserve(size_t(spr.header.num_frames));
    for (int32_t i = 0; i < spr.header.num_frames; ++i) {
        spr.frames.push_back(read_frame(in, spr.header, size_t(i), tally, spr.warnings));
    }
    if (tally.pictures_over_max > 0) {
        spr.warnings.push_back(std::to_string(tally.pictures_over_max) +
                               " picture(s) larger than the header's maximum " +
                               std::to_string(spr.header.max_width) + "x" +
                               std::to_string(spr.header.max_height));
    }
    spr.trailing_bytes = in.remaining();
    if (spr.trailing_bytes > 0) {
        spr.warnings.push_back(std::to_string(spr.trailing_bytes) +
                               " trailing byte(s) after the last frame at offset " +
                               std::to_string(in.tell()) + " (ignored)");
    }
    return spr;
}

}  // namespace

const char* sprite_type_name(int32_t type) {
    switch (type) {
        case int32_t(SpriteType::ViewParallelUpright):
            return "vp_parallel_upright";
        case int32_t(SpriteType::FacingUpright):
            return "facing_upright";
        case int32_t(SpriteType::ViewParallel):
            return "vp_parallel";
        case int32_t(SpriteType::Oriented):
            return "oriented";
        case int32_t(SpriteType::ViewParallelOriented):
            return "vp_parallel_oriented";
        default:
            return "unknown";
    }
}

Result<Spr> parse_spr(std::span<const uint8_t> data, const std::string& name) {
    return capture_errors(name, [&] { return parse_spr_body(data, name); });
}

}  // namespace nq
