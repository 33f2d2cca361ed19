// One nprquake run shared by every test that needs it. An engine run costs seconds (tens of
// seconds for a whole timedemo under ASan on llvmpipe), so a run that writes several
// screenshots serves several tests.
//
// Sharing inside one process is not enough: ctest runs every discovered GoogleTest case in a
// process of its own, so a fixture's SetUpTestSuite would run once per test. The run's files
// therefore live in a directory of the test session, guarded by a file lock: the first test
// process that asks for a run makes it, later ones (also concurrent ones, with ctest -j) wait
// for it and read its results. A session is one ctest invocation (keyed by the ctest process
// and its start time) or, outside ctest, the test process itself; results never outlive it,
// and directories of finished sessions are removed by the next one.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "support/engine_run.h"

namespace nq::test {

struct SharedRun {
    std::string dir;  // the run's own directory: the arguments put screenshots etc. here
    ProcessResult result;
};

// Arguments of the run, given its directory.
using RunArguments = std::function<std::vector<std::string>(const std::string& dir)>;

// The run named `key` of this session, made now if nobody made it yet. Asking again for a key
// with different arguments is a programming error (throws).
const SharedRun& shared_nprquake_run(const std::string& key, const RunArguments& arguments,
                                     double timeout_seconds = 300);

}  // namespace nq::test
