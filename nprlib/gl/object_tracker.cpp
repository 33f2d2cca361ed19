#include "gl/object_tracker.h"

namespace nq::npr::gl {

const char* object_kind_name(ObjectKind kind) {
    switch (kind) {
        case ObjectKind::buffer:
            return "buffer";
        case ObjectKind::vertex_array:
            return "vertex array";
        case ObjectKind::texture:
            return "texture";
        case ObjectKind::framebuffer:
            return "framebuffer";
        case ObjectKind::shader:
            return "shader";
        case ObjectKind::program:
            return "program";
        case ObjectKind::sync:
            return "sync";
        case ObjectKind::query:
            return "query";
        case ObjectKind::count:
            break;
    }
    return "?";
}

int ObjectTracker::total_live() const {
    int total = 0;
    for (int n : live_) total += n;
    return total;
}

}  // namespace nq::npr::gl
