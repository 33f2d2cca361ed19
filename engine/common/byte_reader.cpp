#include "common/byte_reader.h"

#include <cmath>
#include <cstring>

namespace nq {

ByteReader::ByteReader(std::span<const uint8_t> data, std::string file, uint64_t base)
    : data_(data), file_(std::move(file)), base_(base) {}

void ByteReader::restart(std::span<const uint8_t> data, uint64_t base) {
    data_ = data;
    base_ = base;
    pos_ = 0;
}

void ByteReader::fail_at(size_t pos, std::string message) const {
    throw FormatError(Error{file_, base_ + pos, std::move(message)});
}

void ByteReader::need(size_t n, std::string_view what) const {
    if (n > remaining()) {
        fail("unexpected end of data reading " + std::string(what) + " (" + std::to_string(n) +
             " bytes needed, " + std::to_string(remaining()) + " left)");
    }
}

void ByteReader::seek(size_t pos) {
    if (pos > data_.size()) {
        fail("seek to " + std::to_string(pos) + " past end (size " + std::to_string(size()) + ")");
    }
    pos_ = pos;
}

void ByteReader::skip(size_t n) {
    need(n, "skipped bytes");
    pos_ += n;
}

uint8_t ByteReader::u8() {
    need(1, "u8");
    return data_[pos_++];
}

uint16_t ByteReader::u16() {
    need(2, "u16");
    uint16_t v = static_cast<uint16_t>(data_[pos_] | (data_[pos_ + 1] << 8));
    pos_ += 2;
    return v;
}

uint32_t ByteReader::u32() {
    need(4, "u32");
    uint32_t v = static_cast<uint32_t>(data_[pos_]) | (static_cast<uint32_t>(data_[pos_ + 1]) << 8) |
                 (static_cast<uint32_t>(data_[pos_ + 2]) << 16) |
                 (static_cast<uint32_t>(data_[pos_ + 3]) << 24);
    pos_ += 4;
    return v;
}

float ByteReader::f32() {
    uint32_t bits = u32();
    float f;
    std::memcpy(&f, &bits, sizeof f);
    return f;
}

float ByteReader::f32_finite() {
    size_t at = pos_;
    float f = f32();
    if (!std::isfinite(f)) fail_at(at, "float is NaN or infinite");
    return f;
}

std::span<const uint8_t> ByteReader::bytes(size_t n) {
    need(n, "byte block");
    auto s = data_.subspan(pos_, n);
    pos_ += n;
    return s;
}

std::string ByteReader::fixed_string(size_t width) {
    auto raw = bytes(width);
    size_t len = 0;
    while (len < raw.size() && raw[len] != 0) ++len;
    return std::string(reinterpret_cast<const char*>(raw.data()), len);
}

std::string ByteReader::c_string() {
    size_t end = pos_;
    while (end < data_.size() && data_[end] != 0) ++end;
    if (end == data_.size()) fail("string is not terminated before end of data");
    std::string s(reinterpret_cast<const char*>(data_.data() + pos_), end - pos_);
    pos_ = end + 1;
    return s;
}

ByteReader ByteReader::sub(size_t offset, size_t length, std::string_view what) const {
    if (offset > data_.size() || length > data_.size() - offset) {
        fail_at(0, std::string(what) + " [" + std::to_string(offset) + ", +" +
                       std::to_string(length) + ") lies outside the data (size " +
                       std::to_string(size()) + ")");
    }
    return ByteReader(data_.subspan(offset, length), file_, base_ + offset);
}

void ByteReader::require_records(int64_t count, size_t record_size, std::string_view what) const {
    if (count < 0) fail(std::string(what) + ": negative count " + std::to_string(count));
    if (record_size != 0 && static_cast<uint64_t>(count) > remaining() / record_size) {
        fail(std::string(what) + ": count " + std::to_string(count) + " of " +
             std::to_string(record_size) + "-byte records exceeds the " +
             std::to_string(remaining()) + " bytes left");
    }
}

}  // namespace nq
