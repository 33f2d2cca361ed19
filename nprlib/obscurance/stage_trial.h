// vo_compute 2: which of two ways to run the pass's heavy stages (the estimate and the blur) is
// faster on this GPU, measured rather than guessed. The same shader code runs as compute
// programs or over full-screen triangles with the same result (a test compares them), but
// which is faster differs between machines: Mesa's llvmpipe draws the estimate in 0.6x the
// time as a fragment shader, while a data-centre GPU that keeps graphics to a few of its cores
// should favour compute.
//
// A trial alternates the two ways frame by frame (A, B, A, B: a GPU's clock drifts), drops
// each way's first frames (compiling, caches), and keeps the way whose median of the estimate
// and blur together is lower. Both stages go the same way: on llvmpipe the fragment estimate
// with the compute blur read faster stage by stage yet drew no more frames a second than both
// as fragment shaders (a compute dispatch waits for the drawing before it, which no stage's
// time shows). Pure bookkeeping: the GPU times come from StageClock (stage_clock.h).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

namespace nq::npr::obscurance {

enum class StagePath : uint8_t { fragment, compute };
enum class TimedStage : uint8_t { estimate, blur };
inline constexpr int kTimedStages = 2;

class StageTrial {
  public:
    static constexpr int kWarmUpFrames = 3;  // per way, not counted
    static constexpr int kKeptFrames = 7;    // per way, counted (odd: a true median)
    static constexpr int kFrames = 2 * (kWarmUpFrames + kKeptFrames);

    // Forgets what was measured: the next frames are the trial's again.
    void restart() { *this = StageTrial{}; }

    // The way both stages run in trial frame `frame` (0 .. kFrames - 1): compute first.
    static StagePath path_of_frame(int frame) {
        return frame % 2 == 0 ? StagePath::compute : StagePath::fragment;
    }

    // The GPU time of each stage in trial frame `frame`, in nanoseconds (0 for a stage that did
    // not run). Each frame counts once.
    void record(int frame, const std::array<uint64_t, kTimedStages>& nanoseconds);

    // Whether every trial frame has been recorded and the choice made.
    bool decided() const { return recorded_ == kFrames; }
    // The faster way (compute until decided, and where a way's time reads 0).
    StagePath choice() const { return choice_; }
    // Medians over a way's kept frames (0 until decided): of both stages together, of one.
    uint64_t median(StagePath path) const { return total_median_[index(path)]; }
    uint64_t median(TimedStage stage, StagePath path) const {
        return stage_median_[std::size_t(stage)][index(path)];
    }

  private:
    static std::size_t index(StagePath path) { return std::size_t(path); }
    void decide();

    // [way][kept frame][stage]
    std::array<std::array<std::array<uint64_t, kTimedStages>, kKeptFrames>, 2> kept_{};
    std::array<uint64_t, 2> total_median_{};
    std::array<std::array<uint64_t, 2>, kTimedStages> stage_median_{};
    StagePath choice_ = StagePath::compute;
    std::array<bool, kFrames> seen_{};
    int recorded_ = 0;
};

// What a decided trial chose, for the console: "fragment 20.10 ms (estimate 9.99, blur 10.11),
// compute 26.18 ms (estimate 19.72, blur 6.46) -> fragment".
std::string describe_choice(const StageTrial& trial);

}  // namespace nq::npr::obscurance
