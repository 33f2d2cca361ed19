// Writes Quake's network encodings into a byte buffer, for the server's messages and QuakeC's
// WriteByte..WriteEntity. Values a protocol cannot carry are clamped (coordinates) or wrapped
// (angles, integers) as Quake's MSG_Write* do, never refused: a server frame must always go out.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "formats/protocol.h"

namespace nq::server {

class MessageWriter {
  public:
    MessageWriter(std::vector<uint8_t>& out, const protocol::ProtocolState& protocol)
        : out_(out), protocol_(protocol) {}

    void byte(int v) { out_.push_back(uint8_t(v)); }
    void chr(int v) { byte(v); }
    void shrt(int v);
    void lng(int32_t v);
    void flt(float v);
    void string(std::string_view s);  // up to its first NUL, then a NUL
    void coord(float v);
    void angle(float v);    // the protocol's angle (a byte unless 999's flags say otherwise)
    void angle16(float v);  // FitzQuake's 16-bit angle (svc_setangle under 666 uses angle())
    void coords(const std::array<float, 3>& v) {
        for (float c : v) coord(c);
    }
    void angles(const std::array<float, 3>& v) {
        for (float a : v) angle(a);
    }

  private:
    std::vector<uint8_t>& out_;
    const protocol::ProtocolState& protocol_;
};

}  // namespace nq::server
