#include "video/frame_times_file.h"

#include <cstdio>

#include "common/file_io.h"

namespace nq {

std::string append_frame_times(const std::string& path, const FrameTimesHeader& header,
                               std::span<const double> frame_seconds) {
    std::string text = "# " + header.demo + " " + header.plugin + " " +
                       std::to_string(header.width) + "x" + std::to_string(header.height) + " " +
                       std::to_string(frame_seconds.size()) + "\n";
    text.reserve(text.size() + frame_seconds.size() * 10);
    char line[32];
    for (double seconds : frame_seconds) {
        int n = std::snprintf(line, sizeof line, "%.4f\n", seconds * 1000);
        text.append(line, static_cast<size_t>(n));
    }
    return append_file(path, text);
}

}  // namespace nq
