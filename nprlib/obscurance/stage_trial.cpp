#include "obscurance/stage_trial.h"

#include <algorithm>
#include <cstdio>

namespace nq::npr::obscurance {
namespace {

template <std::size_t N>
uint64_t median_of(std::array<uint64_t, N> values) {
    std::nth_element(values.begin(), values.begin() + N / 2, values.end());
    return values[N / 2];
}

}  // namespace

void StageTrial::record(int frame, const std::array<uint64_t, kTimedStages>& nanoseconds) {
    if (frame < 0 || frame >= kFrames || seen_[std::size_t(frame)]) return;
    seen_[std::size_t(frame)] = true;
    const int round = frame / 2;  // the way's own frame count
    if (round >= kWarmUpFrames) {
        kept_[index(path_of_frame(frame))][std::size_t(round - kWarmUpFrames)] = nanoseconds;
    }
    if (++recorded_ == kFrames) decide();
}

void StageTrial::decide() {
    for (std::size_t path = 0; path < 2; ++path) {
        std::array<uint64_t, kKeptFrames> totals{};
        for (std::size_t frame = 0; frame < totals.size(); ++frame) {
            for (uint64_t stage : kept_[path][frame]) totals[frame] += stage;
        }
        total_median_[path] = median_of(totals);
        for (std::size_t stage = 0; stage < std::size_t(kTimedStages); ++stage) {
            std::array<uint64_t, kKeptFrames> times{};
            for (std::size_t frame = 0; frame < times.size(); ++frame) {
                times[frame] = kept_[path][frame][stage];
            }
            stage_median_[stage][path] = median_of(times);
        }
    }
    const uint64_t fragment = total_median_[index(StagePath::fragment)];
    const uint64_t compute = total_median_[index(StagePath::compute)];
    choice_ = fragment > 0 && compute > 0 && fragment < compute ? StagePath::fragment
                                                                : StagePath::compute;
}

std::string describe_choice(const StageTrial& trial) {
    std::string out;
    for (StagePath path : {StagePath::fragment, StagePath::compute}) {
        char part[128];
        std::snprintf(part, sizeof part, "%s%s %.2f ms (estimate %.2f, blur %.2f)",
                      out.empty() ? "" : ", ", path == StagePath::fragment ? "fragment" : "compute",
                      double(trial.median(path)) * 1e-6,
                      double(trial.median(TimedStage::estimate, path)) * 1e-6,
                      double(trial.median(TimedStage::blur, path)) * 1e-6);
        out += part;
    }
    out += trial.choice() == StagePath::fragment ? " -> fragment" : " -> compute";
    return out;
}

}  // namespace nq::npr::obscurance
