// -benchmark DEMO -benchmarkruns N (as DarkPlaces has it): the timedemo N times, then the
// spread over the runs, a line in <userdir>/<game>/benchmark.log, and quit. The first failed
// run ends it with a non-zero exit status and no figures.
#include <filesystem>

#include "app/engine.h"
#include "common/file_io.h"

#ifndef NQ_VERSION
#define NQ_VERSION "unknown"
#endif

namespace nq {

// The first run after the command line's +commands (they set up what it measures); each next
// one ahead of the rest of the command line, which the run then holds again.
void Engine::queue_benchmark() {
    if (!options_.benchmark) return;
    if (!benchmark_) {
        benchmark_.emplace(*options_.benchmark, options_.benchmark_runs);
        return host_.commands().add_text("timedemo \"" + benchmark_->demo() + "\"\n");
    }
    host_.commands().insert_text("timedemo \"" + benchmark_->demo() + "\"\n");
}

void Engine::benchmark_run_done(const FrameSummary& summary) {
    benchmark_->add_run(summary);
    if (!benchmark_->complete()) return;
    print(benchmark_->report());
    log_benchmark({});
    quit_ = true;
}

void Engine::benchmark_failed(const std::string& why) {
    print("benchmark " + benchmark_->demo() + " failed after " +
          std::to_string(benchmark_->runs_done()) + " of " +
          std::to_string(benchmark_->runs_wanted()) + " runs");
    log_benchmark(why);
    exit_status_ = 1;
    quit_ = true;
}

void Engine::log_benchmark(const std::string& failure) {
    BenchmarkContext context;
    context.utc_time = utc_time_now();
    context.engine_version = NQ_VERSION;
    context.gl_renderer = window_->gl_info().renderer;
    // A run that failed at start-up failed before the plugin loaded: the one it was to use.
    context.plugin = plugins_->active() ? plugins_->active_name() : cvars_.r_plugin->string();
    context.width = window_->drawable_width();
    context.height = window_->drawable_height();
    context.command_line = process_command_line();
    const std::string dir = user_dir() + "/" + options_.game.value_or("id1");
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    const std::string error =
        append_file(dir + "/benchmark.log", benchmark_->log_line(context, failure) + "\n");
    print(error.empty() ? "benchmark: logged to " + dir + "/benchmark.log" : "benchmark: " + error);
}

}  // namespace nq
