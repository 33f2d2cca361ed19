// vo_compute 2's bookkeeping (nprlib/obscurance/stage_trial.h) on made-up GPU times: the ways
// alternate, each way's first frames are not counted, the way with the lower median of both
// stages together is kept, and a way that reads no time never wins.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <functional>

#include "obscurance/stage_trial.h"

namespace nq::npr {
namespace {

using obscurance::StagePath;
using obscurance::StageTrial;
using obscurance::TimedStage;
using Times = std::array<uint64_t, obscurance::kTimedStages>;

// Every trial frame recorded in order with the times `at(frame)` gives.
void run_trial(StageTrial& trial, const std::function<Times(int frame)>& at) {
    for (int frame = 0; frame < StageTrial::kFrames; ++frame) {
        EXPECT_FALSE(trial.decided()) << frame;
        trial.record(frame, at(frame));
    }
}

// The index among one path's frames (0 = its first).
int round_of(int frame) {
    return frame / 2;
}

TEST(StageTrial, ThePathsAlternateComputeFirst) {
    static_assert(StageTrial::kFrames % 2 == 0);
    int compute = 0, fragment = 0;
    for (int frame = 0; frame < StageTrial::kFrames; ++frame) {
        const StagePath path = StageTrial::path_of_frame(frame);
        EXPECT_EQ(path, frame % 2 == 0 ? StagePath::compute : StagePath::fragment);
        (path == StagePath::compute ? compute : fragment)++;
    }
    EXPECT_EQ(compute, StageTrial::kWarmUpFrames + StageTrial::kKeptFrames);
    EXPECT_EQ(fragment, compute);
}

// llvmpipe's times at 640x480 (docs/obscurance.md): the estimate 9.9 ms as fragment against
// 21.3 ms as compute, the blur 9.3 against 7.6: fragment is faster for both stages together,
// though not for the blur alone; with the blur's times larger, compute is.
TEST(StageTrial, BothStagesTogetherDecide) {
    for (const uint64_t blur_scale : {1u, 10u}) {
        StageTrial trial;
        EXPECT_EQ(trial.choice(), StagePath::compute);
        run_trial(trial, [&](int frame) -> Times {
            return StageTrial::path_of_frame(frame) == StagePath::fragment
                       ? Times{9'900'000, 9'300'000 * blur_scale}
                       : Times{21'300'000, 7'600'000 * blur_scale};
        });
        ASSERT_TRUE(trial.decided());
        EXPECT_EQ(trial.choice(), blur_scale == 1 ? StagePath::fragment : StagePath::compute);
        EXPECT_EQ(trial.median(StagePath::fragment), 9'900'000u + 9'300'000u * blur_scale);
        EXPECT_EQ(trial.median(StagePath::compute), 21'300'000u + 7'600'000u * blur_scale);
        EXPECT_EQ(trial.median(TimedStage::estimate, StagePath::fragment), 9'900'000u);
        EXPECT_EQ(trial.median(TimedStage::blur, StagePath::compute), 7'600'000u * blur_scale);
        if (blur_scale == 1) {
            EXPECT_EQ(obscurance::describe_choice(trial),
                      "fragment 19.20 ms (estimate 9.90, blur 9.30), compute 28.90 ms (estimate "
                      "21.30, blur 7.60) -> fragment");
        }
    }
}

// The first frames of each way (shader compiles, caches) are dropped: here they would make
// fragment look faster; one slow kept frame (a hitch) does not move the median.
TEST(StageTrial, WarmUpFramesAndOneOutlierDoNotDecide) {
    StageTrial trial;
    run_trial(trial, [](int frame) -> Times {
        const bool fragment = StageTrial::path_of_frame(frame) == StagePath::fragment;
        const int round = round_of(frame);
        if (round < StageTrial::kWarmUpFrames) return fragment ? Times{1, 1} : Times{900, 900};
        if (!fragment && round == StageTrial::kWarmUpFrames) return {50'000, 50'000};  // a hitch
        return fragment ? Times{300, 300} : Times{200 + uint64_t(round), 250};
    });
    ASSERT_TRUE(trial.decided());
    EXPECT_EQ(trial.choice(), StagePath::compute);
    EXPECT_EQ(trial.median(StagePath::fragment), 600u);
    // Kept compute frames: the hitch, then 450 + round for the other four; sorted, the hitch
    // comes last, so the middle one is the third of those four.
    const int after_hitch = StageTrial::kWarmUpFrames + 1;
    EXPECT_EQ(trial.median(StagePath::compute),
              uint64_t(450 + after_hitch + StageTrial::kKeptFrames / 2));
}

// A way whose times read 0 (no timer, nothing ran) never wins: compute stays.
TEST(StageTrial, ZeroTimesKeepCompute) {
    StageTrial trial;
    run_trial(trial, [](int frame) -> Times {
        return StageTrial::path_of_frame(frame) == StagePath::fragment ? Times{100, 0}
                                                                       : Times{0, 0};
    });
    ASSERT_TRUE(trial.decided());
    EXPECT_EQ(trial.choice(), StagePath::compute);
}

// A frame recorded twice, or outside the trial, counts once or not at all; restart forgets.
TEST(StageTrial, EachFrameCountsOnceAndRestartForgets) {
    StageTrial trial;
    trial.record(-1, {1, 1});
    trial.record(StageTrial::kFrames, {1, 1});
    for (int i = 0; i < 3 * StageTrial::kFrames; ++i) trial.record(0, {1, 1});
    EXPECT_FALSE(trial.decided());
    for (int frame = 1; frame < StageTrial::kFrames; ++frame) trial.record(frame, {5, 5});
    ASSERT_TRUE(trial.decided());
    trial.restart();
    EXPECT_FALSE(trial.decided());
    EXPECT_EQ(trial.choice(), StagePath::compute);
    EXPECT_EQ(trial.median(StagePath::fragment), 0u);
}

}  // namespace
}  // namespace nq::npr
