// The process-running helpers the engine tests rely on (support/engine_run.h), checked with
// /bin/sh so a broken helper fails here, not as a puzzling engine failure.
#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>

#include "support/engine_run.h"

namespace nq {
namespace {

using namespace test;

TEST(EngineRunHelpers, CapturesOutputErrorsAndExitStatus) {
    TempDir dir("nq_run_helpers");
    ProcessResult r =
        run_process("/bin/sh", {"-c", "echo out; echo err >&2; echo \"$NQ_PROBE\"; exit 3"},
                    {"NQ_PROBE=from the test"}, 10, dir.path());
    ASSERT_TRUE(r.spawned) << r.describe();
    EXPECT_EQ(r.exit_code, 3);
    EXPECT_EQ(r.signal, 0);
    EXPECT_FALSE(r.timed_out);
    EXPECT_EQ(r.out, "out\nfrom the test\n");
    EXPECT_EQ(r.err, "err\n");
}

TEST(EngineRunHelpers, KillsAProcessThatOutlivesItsLimit) {
    TempDir dir("nq_run_helpers");
    ProcessResult r = run_process("/bin/sh", {"-c", "exec sleep 30"}, {}, 0.3, dir.path());
    EXPECT_TRUE(r.timed_out);
    EXPECT_EQ(r.signal, SIGKILL);
    EXPECT_LT(r.seconds, 5.0);
}

TEST(EngineRunHelpers, ReportsAProgramThatCannotStart) {
    TempDir dir("nq_run_helpers");
    ProcessResult r = run_process(dir.file("missing"), {}, {}, 5, dir.path());
    EXPECT_FALSE(r.spawned);
    EXPECT_NE(r.describe().find("missing"), std::string::npos) << r.describe();
}

TEST(EngineRunHelpers, TempDirIsCreatedAndRemoved) {
    std::string path;
    {
        TempDir dir("nq_run_helpers");
        path = dir.path();
        EXPECT_TRUE(std::filesystem::is_directory(dir.subdir("a/b")));
    }
    EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(EngineRunHelpers, FindsSanitizerReportsAndOnlyThem) {
    EXPECT_EQ(sanitizer_report("renderer: classic\n1720 frames 9.1 seconds 189.0 fps\n"), "");
    EXPECT_EQ(sanitizer_report("x\n==7==ERROR: LeakSanitizer: detected memory leaks\ny\n"),
              "==7==ERROR: LeakSanitizer: detected memory leaks");
    EXPECT_EQ(sanitizer_report("a.cpp:3:5: runtime error: signed integer overflow\n"),
              "a.cpp:3:5: runtime error: signed integer overflow");
    EXPECT_NE(sanitizer_report("==9==ERROR: AddressSanitizer: heap-use-after-free"), "");
}

TEST(EngineRunHelpers, LinesContainingReturnsWholeLines) {
    auto lines = lines_containing("a keeping b\nnothing\nkeeping\n", "keeping");
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_EQ(lines[0], "a keeping b");
    EXPECT_EQ(lines[1], "keeping");
}

}  // namespace
}  // namespace nq
