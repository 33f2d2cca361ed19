// Running the engine binary (or any program) from tests: arguments and environment in, exit
// status, stdout and stderr out, with a wall-clock limit. Plus a scratch directory that removes
// itself. No engine libraries needed: these only spawn processes.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace nq::test {

struct ProcessResult {
    int exit_code = -1;      // the exit status; -1 when the process died of a signal
    int signal = 0;          // the signal that ended it, 0 when it exited
    bool timed_out = false;  // killed (SIGKILL) after the time limit
    bool spawned = false;    // false when the program could not be started at all
    double seconds = 0;      // wall time
    std::string out, err;    // everything it wrote to stdout and stderr

    // One line for failure messages: how it ended, and the tail of stderr.
    std::string describe() const;
};

// Runs `program` with `args` and the current environment plus `env` ("NAME=value" entries
// replace same-named variables). stdout and stderr go to files in `capture_dir` (which must
// exist), read back once the process has ended, so a chatty child can never block on a pipe.
ProcessResult run_process(const std::string& program, const std::vector<std::string>& args,
                          const std::vector<std::string>& env, double timeout_seconds,
                          const std::string& capture_dir, const std::string& cwd = "");

// A fresh directory under the system temp dir, removed with everything in it.
class TempDir {
  public:
    explicit TempDir(std::string_view tag = "nq_test");
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    const std::string& path() const { return path_; }
    std::string file(std::string_view name) const { return path_ + "/" + std::string(name); }
    // Creates (and returns) a subdirectory.
    std::string subdir(std::string_view name) const;

  private:
    std::string path_;
};

// ---- nprquake

std::string nprquake_path();  // bin_dir()/nprquake

// What every headless engine run needs in its environment: SDL's offscreen video driver, and
// under AddressSanitizer the Mesa driver preloaded (see nprquake_environment() in the .cpp).
std::vector<std::string> nprquake_environment();

// Runs nprquake with `args` (and nprquake_environment() plus `extra_env`); its output files
// land in `capture_dir`.
ProcessResult run_nprquake(const std::vector<std::string>& args, const std::string& capture_dir,
                           double timeout_seconds = 120,
                           const std::vector<std::string>& extra_env = {});

// Runs the build's tool `name` (bin_dir()/name: mdltool, demotool, paktool...) with `args`,
// from directory `cwd` ("" = this one), its output captured in a scratch directory.
ProcessResult run_tool(const std::string& name, const std::vector<std::string>& args,
                       const std::string& cwd = "", double timeout_seconds = 120);

// The first line of a sanitizer report in `text` (AddressSanitizer, LeakSanitizer,
// UndefinedBehaviorSanitizer "runtime error:"), or "" when there is none.
std::string sanitizer_report(std::string_view text);

// The lines of `text` that contain `needle`.
std::vector<std::string> lines_containing(std::string_view text, std::string_view needle);

}  // namespace nq::test
