#include "obscurance/stage_clock.h"

#include <epoxy/gl.h>

namespace nq::npr::obscurance {

void StageClock::stamp(int frame, int stamp) {
    if (frame < 0 || frame >= StageTrial::kFrames || stamp < 0 || stamp >= kStamps) return;
    gl::Query& query = queries_[size_t(frame)][size_t(stamp)];
    if (!query) query = gl::Query::create(tracker_);
    glQueryCounter(query.id(), GL_TIMESTAMP);
}

bool StageClock::read(int frame, std::array<uint64_t, kTimedStages>& nanoseconds) const {
    if (frame < 0 || frame >= StageTrial::kFrames) return false;
    const auto& stamps = queries_[size_t(frame)];
    for (const gl::Query& query : stamps) {
        if (!query) return false;
    }
    // Queries complete in order: the last one ready means all of them are.
    GLint ready = GL_FALSE;
    glGetQueryObjectiv(stamps[kStamps - 1].id(), GL_QUERY_RESULT_AVAILABLE, &ready);
    if (ready != GL_TRUE) return false;
    std::array<GLuint64, kStamps> at{};
    for (size_t i = 0; i < at.size(); ++i) {
        glGetQueryObjectui64v(stamps[i].id(), GL_QUERY_RESULT, &at[i]);
    }
    for (size_t stage = 0; stage < size_t(kTimedStages); ++stage) {
        nanoseconds[stage] = at[stage + 1] > at[stage] ? at[stage + 1] - at[stage] : 0;
    }
    return true;
}

void StageClock::reset() {
    for (auto& stamps : queries_) {
        for (gl::Query& query : stamps) query.reset();
    }
}

}  // namespace nq::npr::obscurance
