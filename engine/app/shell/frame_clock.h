// The engine's wall clock: seconds since start-up, each frame's real duration, and the moment
// the first frame was done (the start-up report).
#pragma once

#include <chrono>
#include <optional>

namespace nq {

class FrameClock {
  public:
    FrameClock() : start_(now()), last_frame_(start_) {}

    // Steady seconds (their zero means nothing; differences do).
    static double now() {
        using Clock = std::chrono::steady_clock;
        return std::chrono::duration<double>(Clock::now().time_since_epoch()).count();
    }
    double since_start(double at) const { return at - start_; }

    // The frame starting at `at`: its real duration since the previous frame began.
    double begin_frame(double at) {
        const double frame_time = at - last_frame_;
        last_frame_ = at;
        return frame_time;
    }
    // Start-up is over (the frames run from here): the next frame's duration starts now.
    void restart_frames() { last_frame_ = now(); }

    // Seconds from start-up to the first frame done, once (the first call); empty afterwards.
    std::optional<double> first_frame_done() {
        if (first_frame_done_) return std::nullopt;
        first_frame_done_ = true;
        return now() - start_;
    }

  private:
    double start_;
    double last_frame_;
    bool first_frame_done_ = false;
};

}  // namespace nq
