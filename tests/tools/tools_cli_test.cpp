// What every command-line tool shares: --help prints the usage to stdout and exits 0, and
// options may come before or after the file arguments (GNU style).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/engine_run.h"
#include "support/test_data.h"

namespace nq {
namespace {

TEST(ToolsCli, EveryToolPrintsItsUsageForHelp) {
    for (const char* tool : {"pak", "demotool", "mdltool", "edgequality", "serverbench",
                             "vo_samples", "vo_reference"}) {
        const test::ProcessResult r = test::run_tool(tool, {"--help"});
        EXPECT_EQ(r.exit_code, 0) << tool << ": " << r.describe();
        EXPECT_NE(r.out.find("usage"), std::string::npos) << tool << " printed:\n" << r.out;
    }
}

TEST(ToolsCli, DemotoolTakesOptionsBeforeOrAfterTheFile) {
    const std::string demo = test::lq1_dir() + "/demo.dem";
    const test::ProcessResult after = test::run_tool("demotool", {"info", demo, "--json"});
    const test::ProcessResult before = test::run_tool("demotool", {"info", "--json", demo});
    ASSERT_EQ(after.exit_code, 0) << after.describe();
    ASSERT_EQ(before.exit_code, 0) << before.describe();
    EXPECT_EQ(after.out, before.out);
    EXPECT_NE(after.out.find("\"protocol\": 666"), std::string::npos);
    const test::ProcessResult dump =
        test::run_tool("demotool", {"dump", "--count", "1", demo, "--from", "1"});
    ASSERT_EQ(dump.exit_code, 0) << dump.describe();
    EXPECT_NE(dump.out.find("block 1  offset"), std::string::npos) << dump.out.substr(0, 300);
    // Two files, or none, is a usage error.
    EXPECT_EQ(test::run_tool("demotool", {"info", demo, demo}).exit_code, 2);
    EXPECT_EQ(test::run_tool("demotool", {"info", "--json"}).exit_code, 2);
}

}  // namespace
}  // namespace nq
