#include "client/demo_recorder.h"

#include <bit>
#include <cerrno>
#include <cstring>

namespace nq {

namespace {

void put_u32(uint8_t* out, uint32_t v) {
    for (int i = 0; i < 4; ++i) out[i] = uint8_t(v >> (8 * i));
}

}  // namespace

std::string DemoRecorder::open(const std::string& path, int cd_track) {
    close();
    file_ = std::fopen(path.c_str(), "wb");
    if (!file_) return "cannot create " + path + ": " + std::strerror(errno);
    path_ = path;
    blocks_ = 0;
    const std::string header = std::to_string(cd_track) + "\n";
    bytes_ = std::fwrite(header.data(), 1, header.size(), file_);
    return {};
}

bool DemoRecorder::write_block(const std::array<float, 3>& view_angles,
                               std::span<const uint8_t> message) {
    if (!file_) return false;
    uint8_t head[16];
    put_u32(head, uint32_t(message.size()));
    for (int i = 0; i < 3; ++i)
        put_u32(head + 4 + 4 * i, std::bit_cast<uint32_t>(view_angles[size_t(i)]));
    const bool ok = std::fwrite(head, 1, sizeof head, file_) == sizeof head &&
                    std::fwrite(message.data(), 1, message.size(), file_) == message.size();
    if (!ok) {
        close();
        return false;
    }
    ++blocks_;
    bytes_ += sizeof head + message.size();
    return true;
}

uint64_t DemoRecorder::close() {
    if (!file_) return 0;
    std::fclose(file_);
    file_ = nullptr;
    return bytes_;
}

}  // namespace nq
