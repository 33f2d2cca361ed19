// The -benchframes file: every counted frame time of a timedemo, so a report can draw the
// whole distribution (a CDF), not just the percentiles. Written once the timedemo has ended,
// from the times the recorder already holds: the frame loop does no extra work for it.
//
// Format, appended per timedemo: a line "# <demo> <plugin> <W>x<H> <frames>", then one frame
// time in milliseconds per line, in the order the frames ran (the first frame, which
// timedemo does not count, left out).
#pragma once

#include <span>
#include <string>

namespace nq {

struct FrameTimesHeader {
    std::string demo;
    std::string plugin;
    int width = 0;
    int height = 0;
};

// "" on success, else a message naming the file.
std::string append_frame_times(const std::string& path, const FrameTimesHeader& header,
                               std::span<const double> frame_seconds);

}  // namespace nq
