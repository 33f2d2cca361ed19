// GPU timestamps around the obscurance pass's estimate and blur in each frame of a StageTrial
// (stage_trial.h), read back a few frames later, never waiting for the GPU. Timestamp queries
// are core OpenGL since 3.3; the trial runs only where compute shaders are (4.3).
#pragma once

#include <array>
#include <cstdint>

#include "gl/handles.h"
#include "obscurance/stage_trial.h"

namespace nq::npr::obscurance {

class StageClock {
  public:
    // Stamps of a frame: before the estimate, between the estimate and the blur, after the blur.
    static constexpr int kStamps = kTimedStages + 1;

    explicit StageClock(gl::ObjectTracker* tracker = nullptr) : tracker_(tracker) {}

    // Stamp `stamp` (0 .. kStamps - 1) of trial frame `frame`: taken when the GPU gets there.
    void stamp(int frame, int stamp);
    // The stage times of `frame`, once its stamps have all arrived; false (and nothing
    // waited for) while they have not, or when they were never taken.
    bool read(int frame, std::array<uint64_t, kTimedStages>& nanoseconds) const;

    void reset();  // deletes the queries (the context is going)

  private:
    gl::ObjectTracker* tracker_;
    std::array<std::array<gl::Query, kStamps>, StageTrial::kFrames> queries_;
};

}  // namespace nq::npr::obscurance
