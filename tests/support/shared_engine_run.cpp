#include "support/shared_engine_run.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <stdexcept>

namespace nq::test {

namespace fs = std::filesystem;

namespace {

std::string read_line(const std::string& path) {
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);
    return line;
}

// Field 22 of /proc/<pid>/stat (start time in clock ticks since boot), "" if there is none.
// Together with the pid it names a process unambiguously.
std::string process_start_time(const std::string& pid) {
    std::string stat = read_line("/proc/" + pid + "/stat");
    size_t paren = stat.rfind(')');
    if (paren == std::string::npos) return {};
    std::istringstream fields(stat.substr(paren + 2));
    std::string field;
    for (int i = 3; i <= 22 && fields >> field; ++i) {
    }
    return field;
}

fs::path runs_root() {
    return fs::temp_directory_path() / "nq_engine_runs";
}

// Removes the directories of sessions whose process is gone.
void remove_finished_sessions() {
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(runs_root(), ec)) {
        std::string name = entry.path().filename().string();  // <kind>-<pid>-<start time>
        size_t a = name.find('-'), b = name.rfind('-');
        if (a == std::string::npos || a == b) continue;
        std::string pid = name.substr(a + 1, b - a - 1);
        if (process_start_time(pid) != name.substr(b + 1)) fs::remove_all(entry.path(), ec);
    }
}

// A directory for this session's runs: shared by all tests of one ctest invocation, private
// to this process otherwise (then removed at exit).
class SessionDir {
  public:
    SessionDir() {
        std::string parent = std::to_string(getppid());
        bool under_ctest = read_line("/proc/" + parent + "/comm") == "ctest";
        std::string owner = under_ctest ? parent : std::to_string(getpid());
        path_ = runs_root() /
                ((under_ctest ? "ctest-" : "process-") + owner + "-" + process_start_time(owner));
        private_ = !under_ctest;
        fs::create_directories(runs_root());
        remove_finished_sessions();
        fs::create_directories(path_);
    }
    ~SessionDir() {
        std::error_code ec;
        if (private_) fs::remove_all(path_, ec);
    }
    const fs::path& path() const { return path_; }

  private:
    fs::path path_;
    bool private_ = true;
};

const SessionDir& session() {
    static SessionDir dir;
    return dir;
}

// An exclusive flock on a file, held for the guard's lifetime.
class FileLock {
  public:
    explicit FileLock(const fs::path& path) : fd_(::open(path.c_str(), O_RDWR | O_CREAT, 0644)) {
        if (fd_ < 0 || flock(fd_, LOCK_EX) != 0) {
            throw std::runtime_error("cannot lock " + path.string());
        }
    }
    ~FileLock() {
        flock(fd_, LOCK_UN);
        ::close(fd_);
    }
    FileLock(const FileLock&) = delete;
    FileLock& operator=(const FileLock&) = delete;

  private:
    int fd_;
};

std::string joined(const std::vector<std::string>& args) {
    std::string out;
    for (const auto& a : args) out += a + '\n';
    return out;
}

std::string read_all(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

void write_all(const fs::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

// The finished run recorded in `dir`, if it was made with `args`.
bool load_recorded(const fs::path& dir, const std::string& args, ProcessResult& out) {
    if (!fs::exists(dir / "result.txt")) return false;
    if (read_all(dir / "arguments.txt") != args) {
        throw std::logic_error("shared run " + dir.string() + " asked for with other arguments");
    }
    std::istringstream fields(read_all(dir / "result.txt"));
    fields >> out.exit_code >> out.signal >> out.timed_out >> out.spawned >> out.seconds;
    out.out = read_all(dir / "stdout.txt");
    out.err = read_all(dir / "stderr.txt");
    return true;
}

void record(const fs::path& dir, const std::string& args, const ProcessResult& r) {
    write_all(dir / "arguments.txt", args);
    std::ostringstream fields;
    fields << r.exit_code << ' ' << r.signal << ' ' << r.timed_out << ' ' << r.spawned << ' '
           << r.seconds << '\n';
    write_all(dir / "result.txt", fields.str());  // last: its presence marks a finished run
}

}  // namespace

const SharedRun& shared_nprquake_run(const std::string& key, const RunArguments& arguments,
                                     double timeout_seconds) {
    static std::mutex mutex;
    static std::map<std::string, std::unique_ptr<SharedRun>> runs;
    std::lock_guard<std::mutex> in_process(mutex);
    if (auto it = runs.find(key); it != runs.end()) return *it->second;

    const fs::path dir = session().path() / key;
    auto run = std::make_unique<SharedRun>();
    run->dir = dir.string();
    const std::string args = joined(arguments(run->dir));

    FileLock across_processes(session().path() / (key + ".lock"));
    if (!load_recorded(dir, args, run->result)) {
        fs::remove_all(dir);
        fs::create_directories(dir);
        run->result = run_nprquake(arguments(run->dir), run->dir, timeout_seconds);
        record(dir, args, run->result);
    }
    return *runs.emplace(key, std::move(run)).first->second;
}

}  // namespace nq::test
