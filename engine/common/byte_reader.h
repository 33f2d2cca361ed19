// Bounds-checked little-endian reader over an immutable byte span. Every read that would leave
// the span, every count that could not fit in the remaining bytes, throws FormatError naming
// the file and the absolute offset. Parsers catch it at their entry point (see capture_errors).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "common/error.h"

namespace nq {

class ByteReader {
public:
    // `base` is the absolute offset of data[0] in the named file, so errors in a sub-reader
    // (a lump, a pak entry) still point at the right byte of the file.
    ByteReader(std::span<const uint8_t> data, std::string file, uint64_t base = 0);

    // Starts over on `data` (at `base` in the same file), keeping the file name: a reader
    // reused for buffer after buffer copies the name once, not per buffer.
    void restart(std::span<const uint8_t> data, uint64_t base = 0);

    size_t size() const { return data_.size(); }
    size_t tell() const { return pos_; }
    size_t remaining() const { return data_.size() - pos_; }
    bool at_end() const { return pos_ == data_.size(); }
    const std::string& file() const { return file_; }
    uint64_t absolute(size_t pos) const { return base_ + pos; }

    void seek(size_t pos);
    void skip(size_t n);

    uint8_t u8();
    int8_t i8() { return static_cast<int8_t>(u8()); }
    uint16_t u16();
    int16_t i16() { return static_cast<int16_t>(u16()); }
    uint32_t u32();
    int32_t i32() { return static_cast<int32_t>(u32()); }
    float f32();         // any bit pattern
    float f32_finite();  // rejects NaN and infinities
    std::span<const uint8_t> bytes(size_t n);
    // A fixed-width, NUL-padded name field (e.g. 16 bytes in WAD and BSP, 56 in PAK).
    std::string fixed_string(size_t width);
    // A NUL-terminated string; fails if no NUL before the end of the span.
    std::string c_string();

    // A reader over [offset, offset + length) of this one; fails if that range is outside.
    ByteReader sub(size_t offset, size_t length, std::string_view what) const;

    // Validates that `count` records of `record_size` bytes fit in what remains (or in
    // `available` bytes). Use before reserving memory for a count read from the file.
    void require_records(int64_t count, size_t record_size, std::string_view what) const;

    [[noreturn]] void fail(std::string message) const { fail_at(pos_, std::move(message)); }
    [[noreturn]] void fail_at(size_t pos, std::string message) const;

private:
    void need(size_t n, std::string_view what) const;

    std::span<const uint8_t> data_;
    std::string file_;
    uint64_t base_ = 0;
    size_t pos_ = 0;
};

}  // namespace nq
