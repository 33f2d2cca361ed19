#include "app/timedemo/benchmark_runs.h"

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <iterator>

namespace nq {
namespace {

double median_of(std::vector<double> values) {
    if (values.empty()) return 0;
    std::sort(values.begin(), values.end());
    const size_t n = values.size();
    return n % 2 == 1 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

template <typename Field>
std::vector<double> field_of(std::span<const FrameSummary> runs, Field field) {
    std::vector<double> out;
    out.reserve(runs.size());
    for (const FrameSummary& run : runs) out.push_back(run.*field);
    return out;
}

std::string quoted_if_needed(const std::string& arg) {
    if (!arg.empty() && arg.find_first_of(" \t\"'") == std::string::npos) return arg;
    return "\"" + arg + "\"";
}

}  // namespace

BenchmarkSpread spread_of(std::span<const FrameSummary> runs) {
    BenchmarkSpread s;
    s.runs = runs.size();
    if (runs.empty()) return s;
    const std::vector<double> fps = field_of(runs, &FrameSummary::fps);
    s.min_fps = *std::min_element(fps.begin(), fps.end());
    s.max_fps = *std::max_element(fps.begin(), fps.end());
    s.median_fps = median_of(fps);
    s.median_ms = median_of(field_of(runs, &FrameSummary::median_ms));
    s.p95_ms = median_of(field_of(runs, &FrameSummary::p95_ms));
    s.p99_ms = median_of(field_of(runs, &FrameSummary::p99_ms));
    s.low1_fps = median_of(field_of(runs, &FrameSummary::low1_fps));
    return s;
}

BenchmarkRuns::BenchmarkRuns(std::string demo, int runs_wanted)
    : demo_(std::move(demo)), runs_wanted_(std::max(runs_wanted, 1)) {
    runs_.reserve(static_cast<size_t>(runs_wanted_));
}

std::string BenchmarkRuns::report() const {
    const BenchmarkSpread s = spread_of(runs_);
    char text[400];
    std::snprintf(text, sizeof text,
                  "benchmark %s: %zu runs, fps min %.1f median %.1f max %.1f; frame time (median "
                  "over runs) median %.2f ms, 95th %.2f ms, 99th %.2f ms; 1%% low %.1f fps",
                  demo_.c_str(), s.runs, s.min_fps, s.median_fps, s.max_fps, s.median_ms, s.p95_ms,
                  s.p99_ms, s.low1_fps);
    return text;
}

std::string BenchmarkRuns::log_line(const BenchmarkContext& c, const std::string& failure) const {
    std::string line = c.utc_time + " | nprquake " + c.engine_version + " | GL_RENDERER " +
                       c.gl_renderer + " | " + c.plugin + " " + std::to_string(c.width) + "x" +
                       std::to_string(c.height) + " | ";
    line += failure.empty() ? report() : "benchmark " + demo_ + ": FAILED: " + failure;
    return line + " | command line: " + c.command_line;
}

std::string utc_time_now() {
    const std::time_t now = std::time(nullptr);
    std::tm utc{};
    gmtime_r(&now, &utc);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
    return text;
}

// /proc files report no size, so the file is read as a stream.
std::string process_command_line() {
    std::ifstream file("/proc/self/cmdline", std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
    if (bytes.empty()) return "(unknown)";
    std::string line, arg;
    for (char c : bytes) {
        if (c != '\0') {
            arg += c;
            continue;
        }
        if (!line.empty()) line += ' ';
        line += quoted_if_needed(arg);
        arg.clear();
    }
    return line;
}

}  // namespace nq
