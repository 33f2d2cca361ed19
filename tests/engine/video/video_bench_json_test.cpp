// The -benchjson record: one compact JSON object per line, appended.
#include <gtest/gtest.h>

#include <fstream>

#include "common/file_io.h"
#include "video/bench_record.h"
#include "support/engine_run.h"
#include "support/video_test_support.h"

namespace nq {
namespace {

BenchRecord sample_record() {
    BenchRecord r;
    r.demo = "demo1";
    r.plugin = "classic";
    r.width = 640;
    r.height = 480;
    r.gl_renderer = "llvmpipe (LLVM 15.0.6, 256 bits)";
    r.gl_version = "4.5 (Core Profile) Mesa 22.3.6";
    r.frames.frames = 200;
    r.frames.seconds = 4;
    r.frames.fps = 50;
    r.frames.median_ms = 19.5;
    r.frames.p95_ms = 25;
    r.frames.p99_ms = 31.25;
    r.frames.low1_fps = 30.5;
    r.frames.distribution_frames = 200;
    r.gpu_timing = true;
    r.gpu_frames = 201;
    r.gpu_passes = {{"world", 100.5, 0.5, 201}, {"outline", 2.25, 0.0112, 201}};
    return r;
}

TEST(VideoBenchJson, RecordHoldsEveryFieldOnOneLine) {
    std::string json = bench_record_json(sample_record());
    EXPECT_EQ(json.find('\n'), std::string::npos);
    EXPECT_EQ(json,
              R"j({"demo":"demo1","plugin":"classic","resolution":"640x480","width":640,)j"
              R"j("height":480,"gl_renderer":"llvmpipe (LLVM 15.0.6, 256 bits)",)j"
              R"j("gl_version":"4.5 (Core Profile) Mesa 22.3.6","frames":200,"seconds":4,)j"
              R"j("fps":50,"median_ms":19.5,"p95_ms":25,"p99_ms":31.25,"low1_fps":30.5,)j"
              R"j("distribution_frames":200,"gpu_timing":true,"gpu_frames":201,"gpu_passes":{)j"
              R"j("world":{"total_ms":100.5,"ms_per_frame":0.5,"count":201},)j"
              R"j("outline":{"total_ms":2.25,"ms_per_frame":0.0112,"count":201}}})j");
}

TEST(VideoBenchJson, WithoutGpuTimingThePassesAreEmpty) {
    BenchRecord r = sample_record();
    r.gpu_timing = false;
    std::string json = bench_record_json(r);
    EXPECT_NE(json.find(R"("gpu_timing":false)"), std::string::npos);
    EXPECT_NE(json.find(R"("gpu_passes":{})"), std::string::npos);
}

TEST(VideoBenchJson, StringsAreEscaped) {
    BenchRecord r = sample_record();
    r.demo = "my \"demo\"";
    EXPECT_NE(bench_record_json(r).find(R"("demo":"my \"demo\"")"), std::string::npos);
}

TEST(VideoBenchJson, AppendsOneLinePerRun) {
    test::TempDir dir("nq_video");
    std::string path = dir.file("bench.jsonl");
    BenchRecord first = sample_record(), second = sample_record();
    second.plugin = "technical";
    ASSERT_EQ(append_bench_record(path, first), "");
    ASSERT_EQ(append_bench_record(path, second), "");

    std::ifstream in(path);
    std::string line1, line2, line3;
    ASSERT_TRUE(std::getline(in, line1));
    ASSERT_TRUE(std::getline(in, line2));
    EXPECT_FALSE(std::getline(in, line3));
    EXPECT_EQ(line1, bench_record_json(first));
    EXPECT_EQ(line2, bench_record_json(second));
}

TEST(VideoBenchJson, UnwritablePathIsAnError) {
    std::string error =
        append_bench_record("/nonexistent_dir_for_nq_test/b.jsonl", sample_record());
    EXPECT_NE(error.find("/nonexistent_dir_for_nq_test/b.jsonl"), std::string::npos) << error;
}

}  // namespace
}  // namespace nq
