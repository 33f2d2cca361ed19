#include "server/message_writer.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace nq::server {

namespace {

// Rounds v * scale to the nearest integer in [lo, hi]; NaN becomes 0.
int64_t clamp_round(double v, double scale, int64_t lo, int64_t hi) {
    if (std::isnan(v)) return 0;
    return int64_t(std::clamp(std::round(v * scale), double(lo), double(hi)));
}

uint32_t rmq_flags(const protocol::ProtocolState& p) {
    return p.protocol == protocol::kRmq ? p.flags : 0;
}

}  // namespace

void MessageWriter::shrt(int v) {
    byte(v & 0xff);
    byte((v >> 8) & 0xff);
}

void MessageWriter::lng(int32_t v) {
    const uint32_t u = uint32_t(v);
    for (int i = 0; i < 4; ++i) byte(int((u >> (8 * i)) & 0xff));
}

void MessageWriter::flt(float v) {
    lng(int32_t(std::bit_cast<uint32_t>(v)));
}

void MessageWriter::string(std::string_view s) {
    s = s.substr(0, s.find('\0'));
    out_.insert(out_.end(), s.begin(), s.end());
    byte(0);
}

void MessageWriter::coord(float v) {
    const uint32_t flags = rmq_flags(protocol_);
    if (flags & protocol::PRFL_FLOATCOORD) return flt(v);
    if (flags & protocol::PRFL_INT32COORD) {
        return lng(int32_t(clamp_round(v, 16.0, INT32_MIN, INT32_MAX)));
    }
    if (flags & protocol::PRFL_24BITCOORD) {
        const double clamped = std::isnan(v) ? 0.0 : std::clamp(double(v), -32768.0, 32767.0);
        double whole = std::floor(clamped);
        int64_t fraction = clamp_round(clamped - whole, 255.0, 0, 255);
        if (fraction == 255 && whole < 32767) {
            whole += 1;
            fraction = 0;
        }
        shrt(int(whole));
        return byte(int(fraction));
    }
    shrt(int(clamp_round(v, 8.0, -32768, 32767)));
}

void MessageWriter::angle(float v) {
    const uint32_t flags = rmq_flags(protocol_);
    if (flags & protocol::PRFL_FLOATANGLE) return flt(v);
    if (flags & protocol::PRFL_SHORTANGLE) return angle16(v);
    const double turn = std::isfinite(v) ? std::fmod(double(v), 360.0) : 0.0;
    byte(int(int64_t(std::round(turn * 256.0 / 360.0)) & 0xff));
}

void MessageWriter::angle16(float v) {
    const double turn = std::isfinite(v) ? std::fmod(double(v), 360.0) : 0.0;
    shrt(int(int64_t(std::round(turn * 65536.0 / 360.0)) & 0xffff));
}

}  // namespace nq::server
