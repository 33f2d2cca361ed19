// Where music comes from: decoded 16-bit stereo PCM, read in chunks into the caller's buffer
// (nothing is allocated while reading). Ogg Vorbis through Debian's libvorbisfile, or a WAV
// held in memory.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "common/result.h"

namespace nq {

class PcmSource {
  public:
    virtual ~PcmSource() = default;
    // Up to out.size() / 2 interleaved stereo frames; 0 at the end of the stream.
    virtual size_t read(std::span<int16_t> out) = 0;
    virtual bool rewind() = 0;
    virtual int rate() const = 0;
    virtual uint64_t total_frames() const = 0;  // at rate()
};

// "music/track03.ogg" etc.: `bytes` is the whole file; it is decoded as it is read.
Result<std::unique_ptr<PcmSource>> open_ogg(std::vector<uint8_t> bytes, const std::string& name);
Result<std::unique_ptr<PcmSource>> open_wav_music(std::span<const uint8_t> bytes,
                                                  const std::string& name);

}  // namespace nq
