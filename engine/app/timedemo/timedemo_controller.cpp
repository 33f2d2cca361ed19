#include "app/timedemo/timedemo_controller.h"

#include <cstdio>
#include <cstdlib>

#include "video/bench_record.h"
#include "video/frame_times_file.h"

namespace nq {

namespace {

std::string format(const char* fmt, double a, double b = 0, double c = 0, double d = 0) {
    char buf[256];
    std::snprintf(buf, sizeof buf, fmt, a, b, c, d);
    return buf;
}

}  // namespace

TimedemoController::TimedemoController(TimedemoContext context) : context_(std::move(context)) {
    if (context_.options->bench_trace) {
        trace_.enable();
        gpu_timers_.set_listener(&trace_);
    }
}

void TimedemoController::register_commands(CommandSystem& commands) {
    commands.add_command(
        "demo_at",
        [this](const CommandArgs& a) {
            if (a.argc() < 3) return context_.print("usage: demo_at <frame> \"<commands>\"");
            schedule_.emplace_back(std::strtoull(a.argv(1).c_str(), nullptr, 10), a.value_from(2));
        },
        "run commands when the next demo reaches a frame (scripted swaps, screenshots)");
}

void TimedemoController::demo_started() {
    after_demo_text_ = context_.host->commands().take_pending_text();
    frame_times_.clear();
    gpu_timers_.reset();
    trace_.clear();
}

// demo_at counts demo frames (messages read), not drawn ones.
void TimedemoController::run_schedule(uint64_t demo_frames) {
    for (auto it = schedule_.begin(); it != schedule_.end();) {
        if (demo_frames >= it->first) {
            context_.host->commands().add_text(it->second + "\n");
            it = schedule_.erase(it);
        } else {
            ++it;
        }
    }
}

void TimedemoController::demo_ended(bool was_timedemo, bool quitting) {
    schedule_.clear();
    if (!after_demo_text_.empty()) {
        context_.host->commands().insert_text(after_demo_text_);
        after_demo_text_.clear();
    }
    if (was_timedemo && benchmark_pending() && !quitting) queue_benchmark();
}

void TimedemoController::update_command_line_job(bool job_demo_playing) {
    if (!command_line_job_ || !context_.host->commands().buffer_empty() ||
        !after_demo_text_.empty()) {
        return;
    }
    if (job_demo_playing) return;  // the attract loop (quake.rc's startdemos) is not the job
    command_line_job_ = false;
}

void TimedemoController::finish_timedemo(const TimedemoRun& run) {
    const FrameSummary summary = frame_times_.summarize();
    const std::string failure = failure_of(run, summary);
    if (!failure.empty()) return timedemo_failed(run, failure);
    report(run, summary);
    write_frame_times(run, summary);
    write_frame_trace(run);
    if (benchmark_) benchmark_run_done(run, summary);
}

std::string TimedemoController::failure_of(const TimedemoRun& run,
                                           const FrameSummary& summary) const {
    if (!run.failure.empty()) return run.failure;
    if (summary.frames == 0) return "no frame was played";
    return {};
}

// Said in the console during play; the process's exit status too when the command line ran it.
void TimedemoController::timedemo_failed(const TimedemoRun& run, const std::string& why) {
    context_.print("timedemo " + run.demo + " failed (no frame rate reported): " + why);
    if (demo_is_job_) context_.fail_process();
    if (benchmark_) benchmark_failed(run, why);
}

void TimedemoController::report(const TimedemoRun& run, const FrameSummary& s) {
    context_.print(quake_timedemo_line(s));
    context_.print(
        format("frame time: median %.2f ms, 95th %.2f ms, 99th %.2f ms; 1%% low %.1f fps",
               s.median_ms, s.p95_ms, s.p99_ms, s.low1_fps));
    gpu_timers_.finish();
    BenchRecord record;
    record.demo = run.demo;
    record.plugin = run.plugin;
    record.width = run.width;
    record.height = run.height;
    record.gl_renderer = run.gl_renderer;
    record.gl_version = run.gl_version;
    record.frames = s;
    record.gpu_passes = gpu_timers_.totals();
    record.gpu_timing = !record.gpu_passes.empty();
    record.gpu_frames = gpu_timers_.frames_timed();
    for (const auto& pass : record.gpu_passes) {
        char line[128];
        std::snprintf(line, sizeof line, "  gpu %-12s %8.3f ms/frame", pass.name.c_str(),
                      pass.ms_per_frame);
        context_.print(line);
    }
    if (context_.options->bench_json) {
        std::string error = append_bench_record(*context_.options->bench_json, record);
        if (!error.empty()) context_.print("benchjson: " + error);
    }
}

void TimedemoController::write_frame_times(const TimedemoRun& run, const FrameSummary& summary) {
    if (!context_.options->bench_frames) return;
    FrameTimesHeader header{run.demo, run.plugin, run.width, run.height};
    std::span<const double> counted = frame_times_.stored_seconds().subspan(1);
    if (counted.size() < summary.frames)
        context_.print("benchframes: more frames than were stored");
    std::string error = append_frame_times(*context_.options->bench_frames, header, counted);
    if (!error.empty()) context_.print("benchframes: " + error);
}

// After report(), which reads back the GPU times of the run's last frames.
void TimedemoController::write_frame_trace(const TimedemoRun& run) {
    if (!context_.options->bench_trace) return;
    TraceHeader header{run.demo, run.plugin, run.width, run.height};
    std::string error = trace_.append_to(*context_.options->bench_trace, header, &gpu_timers_);
    if (!error.empty()) context_.print("benchtrace: " + error);
}

}  // namespace nq
