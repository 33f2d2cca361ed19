#include "formats/lmp.h"

#include "common/byte_reader.h"

namespace nq {

namespace {

// Zero is refused too: a 0 x 2^31 picture holds no pixels yet would send any row loop spinning.
int32_t read_dimension(ByteReader& in, const char* what) {
    size_t at = in.tell();
    int32_t v = in.i32();
    if (v <= 0) {
        in.fail_at(at,
                   std::string("picture ") + what + " must be positive, is " + std::to_string(v));
    }
    return v;
}

void read_pixels(ByteReader& in, Pic& pic) {
    const int64_t count = int64_t{pic.width} * pic.height;
    in.require_records(
        count, 1,
        "picture pixels (" + std::to_string(pic.width) + "x" + std::to_string(pic.height) + ")");
    auto pixels = in.bytes(static_cast<size_t>(count));
    pic.pixels.assign(pixels.begin(), pixels.end());
    if (!in.at_end()) {
        pic.warnings.push_back(std::to_string(in.remaining()) +
                               " trailing byte(s) after the picture (ignored)");
    }
}

bool is_conchars(const WadLump& lump) {
    return lump.type == static_cast<uint8_t>(WadLumpType::ConChars) ||
           names_equal_ignoring_case(lump.name, "conchars");
}

}  // namespace

Result<Pic> parse_qpic(std::span<const uint8_t> data, const std::string& name,
                       uint64_t base_offset) {
    return capture_errors(name, [&] {
        ByteReader in(data, name, base_offset);
        Pic pic;
        pic.width = read_dimension(in, "width");
        pic.height = read_dimension(in, "height");
        read_pixels(in, pic);
        return pic;
    });
}

Result<Pic> parse_conchars(std::span<const uint8_t> data, const std::string& name,
                           uint64_t base_offset) {
    return capture_errors(name, [&] {
        ByteReader in(data, name, base_offset);
        Pic pic;
        pic.width = kConcharsSize;
        pic.height = kConcharsSize;
        read_pixels(in, pic);
        return pic;
    });
}

Result<Pic> parse_wad_pic(const Wad& wad, const WadLump& lump) {
    const bool conchars = is_conchars(lump);
    if (!conchars && lump.type != static_cast<uint8_t>(WadLumpType::QPic)) {
        return Error{wad.file_name, lump.file_offset,
                     "lump '" + lump.name + "' has type " + wad_lump_type_name(lump.type) +
                         ", not a picture"};
    }
    auto bytes = wad.lump_bytes(lump);
    if (!bytes) return bytes.error();
    Result<Pic> pic = conchars ? parse_conchars(*bytes, wad.file_name, lump.file_offset)
                               : parse_qpic(*bytes, wad.file_name, lump.file_offset);
    if (!pic) {
        Error e = pic.error();
        e.message = "lump '" + lump.name + "': " + e.message;
        return e;
    }
    return pic;
}

}  // namespace nq
