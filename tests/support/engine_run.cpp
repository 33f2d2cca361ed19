#include "support/engine_run.h"

#include <dlfcn.h>
#include <fcntl.h>
#include <link.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "support/build_paths.h"
#include "support/raw_bytes.h"

extern char** environ;

namespace nq::test {

namespace fs = std::filesystem;

namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

std::string variable_name(const std::string& entry) {
    return entry.substr(0, entry.find('='));
}

// The current environment with `overrides` replacing same-named entries.
std::vector<std::string> merged_environment(const std::vector<std::string>& overrides) {
    std::vector<std::string> out;
    for (char** e = environ; e && *e; ++e) {
        std::string entry(*e);
        bool replaced = false;
        for (const auto& o : overrides) replaced |= variable_name(o) == variable_name(entry);
        if (!replaced) out.push_back(std::move(entry));
    }
    out.insert(out.end(), overrides.begin(), overrides.end());
    return out;
}

std::vector<char*> c_strings(std::vector<std::string>& strings) {
    std::vector<char*> out;
    for (auto& s : strings) out.push_back(s.data());
    out.push_back(nullptr);
    return out;
}

// Path of a library loaded into this process whose file name contains `fragment`, or "".
std::string loaded_library(const char* fragment) {
    struct Search {
        const char* fragment;
        std::string found;
    } search{fragment, {}};
    dl_iterate_phdr(
        [](dl_phdr_info* info, size_t, void* data) {
            auto* s = static_cast<Search*>(data);
            if (info->dlpi_name &&
                fs::path(info->dlpi_name).filename().string().find(s->fragment) !=
                    std::string::npos) {
                s->found = info->dlpi_name;
                return 1;
            }
            return 0;
        },
        &search);
    return search.found;
}

// Mesa's software rasteriser (llvmpipe), which the offscreen video driver loads.
std::string mesa_software_driver() {
    std::vector<std::string> dirs;
    if (const char* env = std::getenv("LIBGL_DRIVERS_PATH"); env && *env) {
        std::stringstream list(env);
        for (std::string dir; std::getline(list, dir, ':');) dirs.push_back(dir);
    }
    // The multiarch library directory of this system, as the C library's location shows.
    std::string libc = loaded_library("libc.so");
    if (!libc.empty()) {
        std::string dir = fs::path(libc).parent_path().string();
        dirs.push_back(dir + "/dri");
        if (dir.rfind("/lib", 0) == 0) dirs.push_back("/usr" + dir + "/dri");
    }
    for (const char* dir : {"/usr/lib/x86_64-linux-gnu/dri", "/usr/lib64/dri", "/usr/lib/dri"}) {
        dirs.emplace_back(dir);
    }
    for (const auto& dir : dirs) {
        std::error_code ec;
        if (fs::exists(dir + "/swrast_dri.so", ec)) return dir + "/swrast_dri.so";
    }
    return {};
}

}  // namespace

std::string ProcessResult::describe() const {
    std::ostringstream s;
    if (!spawned) {
        s << "could not start: " << err;
        return s.str();
    }
    if (timed_out) s << "timed out after " << seconds << " s; ";
    if (signal) s << "killed by signal " << signal << "; ";
    if (!signal) s << "exit status " << exit_code << "; ";
    constexpr size_t kTail = 3000;
    s << "stderr tail:\n" << (err.size() > kTail ? err.substr(err.size() - kTail) : err);
    return s.str();
}

ProcessResult run_process(const std::string& program, const std::vector<std::string>& args,
                          const std::vector<std::string>& env, double timeout_seconds,
                          const std::string& capture_dir, const std::string& cwd) {
    ProcessResult result;
    const std::string out_path = capture_dir + "/stdout.txt";
    const std::string err_path = capture_dir + "/stderr.txt";

    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, out_path.c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err_path.c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (!cwd.empty()) posix_spawn_file_actions_addchdir_np(&actions, cwd.c_str());

    std::vector<std::string> argv_strings{program};
    argv_strings.insert(argv_strings.end(), args.begin(), args.end());
    std::vector<std::string> env_strings = merged_environment(env);
    std::vector<char*> argv = c_strings(argv_strings);
    std::vector<char*> envp = c_strings(env_strings);

    const auto start = std::chrono::steady_clock::now();
    pid_t pid = 0;
    int rc = posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), envp.data());
    posix_spawn_file_actions_destroy(&actions);
    if (rc != 0) {
        result.err = program + ": " + std::strerror(rc);
        return result;
    }
    result.spawned = true;

    int status = 0;
    const auto limit = std::chrono::duration<double>(timeout_seconds);
    while (waitpid(pid, &status, WNOHANG) == 0) {
        if (std::chrono::steady_clock::now() - start > limit) {
            kill(pid, SIGKILL);  // only the child we started
            waitpid(pid, &status, 0);
            result.timed_out = true;
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) result.signal = WTERMSIG(status);
    result.out = text_file(out_path);
    result.err = text_file(err_path);
    return result;
}

TempDir::TempDir(std::string_view tag) {
    std::string pattern = (fs::temp_directory_path() / (std::string(tag) + "_XXXXXX")).string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed for " + pattern);
    path_ = pattern;
}

TempDir::~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
}

std::string TempDir::subdir(std::string_view name) const {
    std::string dir = file(name);
    fs::create_directories(dir);
    return dir;
}

std::string nprquake_path() {
    return bin_dir() + "/nprquake";
}

std::vector<std::string> nprquake_environment() {
    std::vector<std::string> env{"SDL_VIDEODRIVER=offscreen"};
    if (!kAddressSanitizer) return env;
    // At exit SDL unloads the GL driver; LeakSanitizer then finds Mesa's process-lifetime
    // allocations unreachable and reports them from an "<unknown module>" that no suppression
    // can name, failing every run. A library preloaded at start-up is never unloaded, so its
    // globals stay scanned and its allocations reachable. Leaks of the engine and of plugins
    // are still reported (plugins are unloaded, so theirs appear from an unknown module).
    std::string driver = mesa_software_driver();
    if (driver.empty()) return env;
    std::string preload;
    // GCC's dynamic ASan runtime must come first in the initial library list.
    if (std::string asan = loaded_library("libasan.so"); !asan.empty()) preload = asan + ":";
    preload += driver;
    if (const char* existing = std::getenv("LD_PRELOAD"); existing && *existing) {
        preload += std::string(":") + existing;
    }
    env.push_back("LD_PRELOAD=" + preload);
    return env;
}

ProcessResult run_nprquake(const std::vector<std::string>& args, const std::string& capture_dir,
                           double timeout_seconds, const std::vector<std::string>& extra_env) {
    std::vector<std::string> env = nprquake_environment();
    env.insert(env.end(), extra_env.begin(), extra_env.end());
    return run_process(nprquake_path(), args, env, timeout_seconds, capture_dir);
}

ProcessResult run_tool(const std::string& name, const std::vector<std::string>& args,
                       const std::string& cwd, double timeout_seconds) {
    TempDir capture("nq_tool");
    return run_process(bin_dir() + "/" + name, args, {}, timeout_seconds, capture.path(), cwd);
}

std::string sanitizer_report(std::string_view text) {
    for (const char* marker : {"ERROR: AddressSanitizer", "ERROR: LeakSanitizer",
                               "runtime error:", "WARNING: AddressSanitizer"}) {
        auto lines = lines_containing(text, marker);
        if (!lines.empty()) return lines.front();
    }
    return {};
}

std::vector<std::string> lines_containing(std::string_view text, std::string_view needle) {
    std::vector<std::string> out;
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(start, end - start);
        if (line.find(needle) != std::string_view::npos) out.emplace_back(line);
        start = end + 1;
    }
    return out;
}

}  // namespace nq::test
