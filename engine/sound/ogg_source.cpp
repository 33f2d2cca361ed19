// Ogg Vorbis music through libvorbisfile, reading from the file's bytes in memory.
#include <vorbis/vorbisfile.h>

#include <algorithm>
#include <cstring>

#include "sound/pcm_source.h"

namespace nq {
namespace {

constexpr int kLittleEndian = 0, kWord16 = 2, kSigned = 1;

struct MemoryFile {
    std::vector<uint8_t> bytes;
    size_t position = 0;
};

size_t memory_read(void* out, size_t size, size_t count, void* source) {
    auto* f = static_cast<MemoryFile*>(source);
    if (size == 0) return 0;
    const size_t items = std::min(count, (f->bytes.size() - f->position) / size);
    std::memcpy(out, f->bytes.data() + f->position, items * size);
    f->position += items * size;
    return items;
}

int memory_seek(void* source, ogg_int64_t offset, int whence) {
    auto* f = static_cast<MemoryFile*>(source);
    ogg_int64_t base = whence == SEEK_SET   ? 0
                       : whence == SEEK_CUR ? ogg_int64_t(f->position)
                                            : ogg_int64_t(f->bytes.size());
    const ogg_int64_t target = base + offset;
    if (target < 0 || target > ogg_int64_t(f->bytes.size())) return -1;
    f->position = size_t(target);
    return 0;
}

long memory_tell(void* source) {
    return long(static_cast<MemoryFile*>(source)->position);
}

class OggSource final : public PcmSource {
  public:
    explicit OggSource(std::vector<uint8_t> bytes) { file_.bytes = std::move(bytes); }
    ~OggSource() override {
        if (open_) ov_clear(&vf_);
    }

    std::string open() {
        const ov_callbacks callbacks{memory_read, memory_seek, nullptr, memory_tell};
        if (ov_open_callbacks(&file_, &vf_, nullptr, 0, callbacks) != 0) {
            return "not an Ogg Vorbis stream";
        }
        open_ = true;
        const vorbis_info* info = ov_info(&vf_, -1);
        if (!info || info->channels < 1 || info->channels > 2 || info->rate <= 0) {
            return "unsupported channel count or rate";
        }
        channels_ = info->channels;
        rate_ = int(info->rate);
        const ogg_int64_t total = ov_pcm_total(&vf_, -1);
        total_ = total > 0 ? uint64_t(total) : 0;
        return {};
    }

    size_t read(std::span<int16_t> out) override {
        // Mono is read into the first half of `out`, then spread to both sides in place.
        const size_t frames_wanted = out.size() / 2;
        const size_t bytes_wanted = frames_wanted * size_t(channels_) * sizeof(int16_t);
        size_t got = 0;
        while (got < bytes_wanted) {
            int section = 0;
            const long n =
                ov_read(&vf_, reinterpret_cast<char*>(out.data()) + got, int(bytes_wanted - got),
                        kLittleEndian, kWord16, kSigned, &section);
            if (n == OV_HOLE) continue;  // a gap in the data: keep going
            if (n <= 0) break;
            got += size_t(n);
        }
        const size_t frames = got / (size_t(channels_) * sizeof(int16_t));
        if (channels_ == 1) {
            for (size_t i = frames; i-- > 0;) out[2 * i] = out[2 * i + 1] = out[i];
        }
        return frames;
    }

    bool rewind() override { return ov_pcm_seek(&vf_, 0) == 0; }
    int rate() const override { return rate_; }
    uint64_t total_frames() const override { return total_; }

  private:
    MemoryFile file_;
    OggVorbis_File vf_{};
    bool open_ = false;
    int channels_ = 2;
    int rate_ = 0;
    uint64_t total_ = 0;
};

}  // namespace

Result<std::unique_ptr<PcmSource>> open_ogg(std::vector<uint8_t> bytes, const std::string& name) {
    auto source = std::make_unique<OggSource>(std::move(bytes));
    if (std::string why = source->open(); !why.empty()) return Error{name, 0, why};
    return std::unique_ptr<PcmSource>(std::move(source));
}

}  // namespace nq
