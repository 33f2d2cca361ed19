// -benchmark DEMO -benchmarkruns N (as DarkPlaces has it): the timedemo N times, then the
// spread over the runs, a line in <userdir>/<game>/benchmark.log, and quit. The first failed
// run ends it with a non-zero exit status and no figures.
#include <filesystem>

#include "app/timedemo/timedemo_controller.h"
#include "common/file_io.h"

#ifndef NQ_VERSION
#define NQ_VERSION "unknown"
#endif

namespace nq {

void TimedemoController::queue_benchmark() {
    const LaunchOptions& options = *context_.options;
    if (!options.benchmark) return;
    CommandSystem& commands = context_.host->commands();
    if (!benchmark_) {
        benchmark_.emplace(*options.benchmark, options.benchmark_runs);
        return commands.add_text("timedemo \"" + benchmark_->demo() + "\"\n");
    }
    commands.insert_text("timedemo \"" + benchmark_->demo() + "\"\n");
}

void TimedemoController::benchmark_run_done(const TimedemoRun& run, const FrameSummary& summary) {
    benchmark_->add_run(summary);
    if (!benchmark_->complete()) return;
    context_.print(benchmark_->report());
    log_benchmark(run, {});
    context_.quit();
}

void TimedemoController::benchmark_failed(const TimedemoRun& run, const std::string& why) {
    context_.print("benchmark " + benchmark_->demo() + " failed after " +
                   std::to_string(benchmark_->runs_done()) + " of " +
                   std::to_string(benchmark_->runs_wanted()) + " runs");
    log_benchmark(run, why);
    context_.fail_process();
    context_.quit();
}

void TimedemoController::log_benchmark(const TimedemoRun& run, const std::string& failure) {
    BenchmarkContext log;
    log.utc_time = utc_time_now();
    log.engine_version = NQ_VERSION;
    log.gl_renderer = run.gl_renderer;
    log.plugin = run.plugin;
    log.width = run.width;
    log.height = run.height;
    log.command_line = process_command_line();
    const std::string& dir = context_.user_game_dir;
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    const std::string error =
        append_file(dir + "/benchmark.log", benchmark_->log_line(log, failure) + "\n");
    context_.print(error.empty() ? "benchmark: logged to " + dir + "/benchmark.log"
                                 : "benchmark: " + error);
}

}  // namespace nq
