// The timedemo/benchmark wing of the engine: what a timedemo measures (each counted frame's
// time, the GPU pass timers, the -benchtrace trace), how its end is reported (the Quake line,
// percentiles, -benchjson, -benchframes, -benchtrace), -benchmark's repeated runs and their
// benchmark.log line, `demo_at` (commands at a demo frame), and the command line's job: the
// rest of the command line waits for a demo it started, and a timedemo it started that fails
// is the process's exit status. The engine shell tells it when a demo starts and ends and
// describes the run; it never reads the shell's members.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "app/timedemo/benchmark_runs.h"
#include "host/host_core.h"
#include "host/launch_options.h"
#include "video/frame_stats.h"
#include "video/frame_trace.h"
#include "video/gpu_pass_timers.h"

namespace nq {

// What the wing needs of the engine; the pointers outlive the controller.
struct TimedemoContext {
    HostCore* host = nullptr;
    const LaunchOptions* options = nullptr;
    std::string user_game_dir;  // <userdir>/<game>: benchmark.log goes here
    std::function<void(std::string_view)> print;
    std::function<void()> quit;          // the benchmark is over: leave the engine
    std::function<void()> fail_process;  // the command line's job failed: exit status 1
};

// The run being reported, as the engine sees it when the demo ends.
struct TimedemoRun {
    std::string demo;
    std::string failure;  // the demo's own failure (a corrupt message), empty when it played
    std::string plugin;   // the active renderer (the one asked for when none loaded)
    int width = 0;
    int height = 0;
    std::string gl_renderer;
    std::string gl_version;
};

class TimedemoController {
  public:
    explicit TimedemoController(TimedemoContext context);

    void register_commands(CommandSystem& commands);  // demo_at

    // The frame's instrumentation, shared with the renderer dispatch and the host services.
    GpuPassTimers& gpu_timers() { return gpu_timers_; }
    FrameTrace& trace() { return trace_; }

    // -benchmark: the first run after the command line's +commands, each next one ahead of
    // the rest of the command line.
    void queue_benchmark();
    bool benchmark_pending() const { return benchmark_ && !benchmark_->complete(); }

    // A demo was asked for (played or not, a demo the command line asked for is its job).
    void demo_requested() { demo_is_job_ = command_line_job_; }
    // It could not start: said in the console, the process's failure when it was the job.
    void timedemo_failed(const TimedemoRun& run, const std::string& why);
    // It started: the rest of the command line waits for its end; statistics start afresh.
    void demo_started();
    // One counted frame of a timedemo (never allocates).
    void record_frame(double seconds) { frame_times_.record(seconds); }
    // demo_at: queues the commands of every scheduled frame the demo has reached.
    void run_schedule(uint64_t demo_frames);
    // A timedemo ended: its report, or (when it failed) why, and never a frame rate then.
    void finish_timedemo(const TimedemoRun& run);
    // Any demo ended: the schedule goes, the waiting command text runs, and the next
    // benchmark run is queued after a timedemo unless the engine is quitting.
    void demo_ended(bool was_timedemo, bool quitting);

    // Called once a frame: the command line's job is over once its commands and the demos
    // they started are done (`job_demo_playing`: a demo that is not the attract loop plays).
    void update_command_line_job(bool job_demo_playing);
    // The command line started a demo and is still running: the attract loop stays off.
    bool after_command_line_demo() const { return command_line_job_ && demo_is_job_; }

  private:
    std::string failure_of(const TimedemoRun& run, const FrameSummary& summary) const;
    void report(const TimedemoRun& run, const FrameSummary& summary);
    void write_frame_times(const TimedemoRun& run, const FrameSummary& summary);
    void write_frame_trace(const TimedemoRun& run);
    // benchmark_log.cpp
    void benchmark_run_done(const TimedemoRun& run, const FrameSummary& summary);
    void benchmark_failed(const TimedemoRun& run, const std::string& why);
    void log_benchmark(const TimedemoRun& run, const std::string& failure);

    TimedemoContext context_;
    GpuPassTimers gpu_timers_;
    FrameTrace trace_;  // -benchtrace
    FrameTimeRecorder frame_times_;
    std::optional<BenchmarkRuns> benchmark_;
    std::string after_demo_text_;  // the command text that waits for the demo to end
    std::vector<std::pair<uint64_t, std::string>> schedule_;  // demo_at FRAME "commands"
    bool command_line_job_ = true;
    bool demo_is_job_ = false;  // the demo playing was started by the command line's commands
};

}  // namespace nq
