#include "sound/wav.h"

#include <optional>

#include "common/byte_reader.h"

namespace nq {
namespace {

constexpr uint16_t kFormatPcm = 1;
constexpr int kMaxChannels = 2;
// Rates a sound can have: slower ones would grow without bound when resampled.
constexpr uint32_t kMinRate = 1000, kMaxRate = 192000;

struct Chunk {
    uint32_t id = 0;
    size_t offset = 0;  // of the chunk's data, in the file
    size_t size = 0;
};

constexpr uint32_t fourcc(const char (&s)[5]) {
    return uint32_t(uint8_t(s[0])) | uint32_t(uint8_t(s[1])) << 8 | uint32_t(uint8_t(s[2])) << 16 |
           uint32_t(uint8_t(s[3])) << 24;
}

// The chunks of the RIFF body; a last chunk that claims more bytes than the file holds is cut
// at the end of the file (many tools write a wrong size there), as Quake tolerates.
std::vector<Chunk> read_chunks(ByteReader& r) {
    std::vector<Chunk> chunks;
    while (r.remaining() >= 8) {
        Chunk c;
        c.id = r.u32();
        const uint32_t size = r.u32();
        c.offset = r.tell();
        c.size = std::min<size_t>(size, r.remaining());
        chunks.push_back(c);
        r.skip(c.size);
        if ((size & 1) && r.remaining() > 0) r.skip(1);  // chunks are word-aligned
    }
    return chunks;
}

const Chunk* find_chunk(const std::vector<Chunk>& chunks, uint32_t id) {
    for (const Chunk& c : chunks)
        if (c.id == id) return &c;
    return nullptr;
}

struct Format {
    int channels = 0, rate = 0, bits = 0;
};

Format read_format(const ByteReader& file, const Chunk& fmt) {
    ByteReader r = file.sub(fmt.offset, fmt.size, "fmt chunk");
    if (fmt.size < 16) r.fail("fmt chunk of " + std::to_string(fmt.size) + " bytes (16 needed)");
    const uint16_t tag = r.u16();
    if (tag != kFormatPcm) r.fail_at(0, "format " + std::to_string(tag) + " is not PCM (1)");
    Format f;
    f.channels = r.u16();
    const uint32_t rate = r.u32();
    r.skip(6);  // byte rate, block align
    f.bits = r.u16();
    if (f.channels < 1 || f.channels > kMaxChannels)
        r.fail_at(2, std::to_string(f.channels) + " channels (1 or 2 supported)");
    if (rate < kMinRate || rate > kMaxRate)
        r.fail_at(4, "sample rate " + std::to_string(rate) + " outside 1000..192000");
    if (f.bits != 8 && f.bits != 16) r.fail_at(14, std::to_string(f.bits) + " bits per sample");
    f.rate = int(rate);
    return f;
}

// Quake's loop start: the sample offset of the first cue point (32 bytes into the chunk,
// counting its 8-byte header).
std::optional<int> read_loop_start(const ByteReader& file, const Chunk& cue) {
    ByteReader r = file.sub(cue.offset, cue.size, "cue chunk");
    if (cue.size < 28) return std::nullopt;  // no complete cue point
    if (r.u32() == 0) return std::nullopt;   // no cue points
    r.skip(20);                              // id, position, chunk id, chunk start, block start
    const uint32_t start = r.u32();
    if (start > 0x7fffffffu) r.fail_at(24, "loop start " + std::to_string(start));
    return int(start);
}

// Quake's loop length: a LIST chunk whose ltxt purpose (20 bytes into its data) is "mark";
// its sample length (16 bytes in) counts from the loop start.
std::optional<uint32_t> read_loop_length(const ByteReader& file, const Chunk& list) {
    if (list.size < 24) return std::nullopt;
    ByteReader r = file.sub(list.offset, list.size, "LIST chunk");
    r.skip(16);
    const uint32_t length = r.u32();
    if (r.u32() != fourcc("mark")) return std::nullopt;
    return length;
}

std::vector<int16_t> read_mono(const ByteReader& file, const Chunk& data, const Format& f) {
    const size_t frame_bytes = size_t(f.channels) * size_t(f.bits / 8);
    const size_t frames = data.size / frame_bytes;
    ByteReader r = file.sub(data.offset, frames * frame_bytes, "data chunk");
    std::vector<int16_t> out(frames);
    for (size_t i = 0; i < frames; ++i) {
        int sum = 0;
        for (int c = 0; c < f.channels; ++c) {
            // 8-bit PCM is unsigned around 128; 16-bit is signed.
            sum += f.bits == 8 ? (int(r.u8()) - 128) * 256 : int(r.i16());
        }
        out[i] = int16_t(sum / f.channels);
    }
    return out;
}

WavSound parse(ByteReader& r) {
    if (r.size() < 12) r.fail("file of " + std::to_string(r.size()) + " bytes is not a WAV");
    if (r.u32() != fourcc("RIFF")) r.fail_at(0, "no RIFF header");
    r.skip(4);
    if (r.u32() != fourcc("WAVE")) r.fail_at(8, "RIFF file is not WAVE");
    const std::vector<Chunk> chunks = read_chunks(r);
    const Chunk* fmt = find_chunk(chunks, fourcc("fmt "));
    if (!fmt) r.fail_at(12, "no fmt chunk");
    const Chunk* data = find_chunk(chunks, fourcc("data"));
    if (!data) r.fail_at(12, "no data chunk");
    const Format f = read_format(r, *fmt);
    WavSound wav;
    wav.rate = f.rate;
    wav.bits = f.bits;
    wav.channels = f.channels;
    wav.samples = read_mono(r, *data, f);
    const Chunk* cue = find_chunk(chunks, fourcc("cue "));
    if (!cue) return wav;
    std::optional<int> start = read_loop_start(r, *cue);
    if (!start) return wav;
    if (size_t(*start) >= wav.samples.size()) {
        r.fail_at(cue->offset + 24, "loop start " + std::to_string(*start) + " past the " +
                                        std::to_string(wav.samples.size()) + " samples");
    }
    wav.loop_start = *start;
    const Chunk* list = find_chunk(chunks, fourcc("LIST"));
    if (std::optional<uint32_t> length = list ? read_loop_length(r, *list) : std::nullopt) {
        const uint64_t end = uint64_t(*start) + *length;
        if (end > wav.samples.size() || end <= uint64_t(*start)) {
            r.fail_at(list->offset + 16, "loop length " + std::to_string(*length) +
                                             " does not fit the " +
                                             std::to_string(wav.samples.size()) + " samples");
        }
        wav.samples.resize(size_t(end));  // Quake plays up to the loop end and no further
    }
    return wav;
}

}  // namespace

Result<WavSound> parse_wav(std::span<const uint8_t> bytes, const std::string& file) {
    return capture_errors(file, [&]() -> WavSound {
        ByteReader r(bytes, file);
        return parse(r);
    });
}

}  // namespace nq
