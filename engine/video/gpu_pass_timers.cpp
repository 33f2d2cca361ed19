#include "video/gpu_pass_timers.h"

#include <algorithm>
#include <cstring>

#include "video/gl_context_setup.h"

namespace nq {
namespace {

constexpr const char* kBuiltinNames[kBuiltinGpuPasses] = {"world",   "brush",     "alias",
                                                          "sprites", "particles", "post"};

bool timestamps_supported() {
    if (epoxy_gl_version() < 33 && !epoxy_has_gl_extension("GL_ARB_timer_query")) return false;
    GLint bits = 0;
    glGetQueryiv(GL_TIMESTAMP, GL_QUERY_COUNTER_BITS, &bits);
    return bits > 0;  // zero bits: the driver exposes the API but cannot measure
}

}  // namespace

GpuPassTimers::GpuPassTimers() {
    for (const char* name : kBuiltinNames) {
        std::memcpy(names_[num_passes_++].data(), name, std::strlen(name) + 1);
    }
}

GpuPassTimers::~GpuPassTimers() {
    shutdown();
}

bool GpuPassTimers::init(bool enabled) {
    shutdown();
    if (!enabled || !timestamps_supported()) return false;
    for (FrameSlot& slot : slots_) {
        glGenQueries(kMaxGpuMarkersPerFrame, slot.queries.data());
    }
    active_ = true;
    reset();
    return true;
}

void GpuPassTimers::shutdown() {
    if (active_ && gl_context_is_current()) {
        for (FrameSlot& slot : slots_) glDeleteQueries(kMaxGpuMarkersPerFrame, slot.queries.data());
    }
    active_ = false;
    in_frame_ = false;
}

void GpuPassTimers::begin_frame() {
    if (!active_) return;
    if (in_frame_) end_frame();
    if (depth_ > 0 || excess_depth_ > 0) {  // begun outside a frame and never ended
        ++diagnostics_.unbalanced;
        depth_ = excess_depth_ = 0;
    }
    slot_ = (slot_ + 1) % kGpuTimerFramesInFlight;
    FrameSlot& slot = slots_[slot_];
    if (slot.pending) collect(slot);
    slot.count = 0;
    slot.serial = frames_;
    in_frame_ = true;
}

void GpuPassTimers::end_frame() {
    if (!active_ || !in_frame_) return;
    if (depth_ > 0 || excess_depth_ > 0) ++diagnostics_.unbalanced;
    while (depth_ > 0) {
        int pass = open_[--depth_];
        if (pass >= 0) add_marker(pass, false);
    }
    excess_depth_ = 0;
    FrameSlot& slot = slots_[slot_];
    slot.pending = slot.count > 0;
    in_frame_ = false;
    ++frames_;
}

void GpuPassTimers::begin(GpuPass pass) {
    begin_index(static_cast<int>(pass));
}

void GpuPassTimers::begin(std::string_view name) {
    if (!active_) return;
    int pass = find_or_add_pass(name);
    if (pass < 0) ++diagnostics_.unknown_passes;
    begin_index(pass);
}

void GpuPassTimers::begin(const char* name) {
    begin(name ? std::string_view(name) : std::string_view());  // empty: counted as unknown
}

void GpuPassTimers::begin_index(int pass) {
    if (!active_) return;
    if (depth_ == kMaxGpuPassDepth) {
        ++excess_depth_;
        ++diagnostics_.dropped_passes;
        return;
    }
    // Room for this begin, its end and the ends of every pass already open.
    bool room = slots_[slot_].count + depth_ + 2 <= kMaxGpuMarkersPerFrame;
    bool timed = in_frame_ && pass >= 0 && room;
    if (in_frame_ && pass >= 0 && !room) ++diagnostics_.dropped_passes;
    if (timed) add_marker(pass, true);
    open_[depth_++] = static_cast<int8_t>(timed ? pass : -1);
}

void GpuPassTimers::end() {
    if (!active_) return;
    if (excess_depth_ > 0) {
        --excess_depth_;
        return;
    }
    if (depth_ == 0) {
        ++diagnostics_.unbalanced;
        return;
    }
    int pass = open_[--depth_];
    if (pass >= 0 && in_frame_) add_marker(pass, false);
}

void GpuPassTimers::add_marker(int pass, bool begin) {
    FrameSlot& slot = slots_[slot_];
    glQueryCounter(slot.queries[slot.count], GL_TIMESTAMP);
    slot.markers[slot.count] = Marker{static_cast<int8_t>(pass), begin};
    ++slot.count;
    if (begin) ++counts_[pass];
}

void GpuPassTimers::collect(FrameSlot& slot) {
    slot.pending = false;
    if (slot.count == 0) return;
    // Timestamps complete in order, so the last one being ready means all are.
    GLint available = 0;
    glGetQueryObjectiv(slot.queries[slot.count - 1], GL_QUERY_RESULT_AVAILABLE, &available);
    if (!available) ++diagnostics_.stalled_reads;  // the reads below will wait
    for (int i = 0; i < slot.count; ++i) {
        glGetQueryObjectui64v(slot.queries[i], GL_QUERY_RESULT, &timestamps_[i]);
    }
    attribute(slot);
}

// Walks the markers in issue order; the time between two consecutive markers belongs to the
// innermost pass open in between.
void GpuPassTimers::attribute(const FrameSlot& slot) {
    std::array<int8_t, kMaxGpuPassDepth> open{};
    int depth = 0;
    frame_nanoseconds_.fill(0);
    for (int i = 0; i < slot.count; ++i) {
        if (i > 0 && depth > 0 && timestamps_[i] > timestamps_[i - 1]) {
            frame_nanoseconds_[open[depth - 1]] += timestamps_[i] - timestamps_[i - 1];
        }
        const Marker& m = slot.markers[i];
        if (m.begin && depth < kMaxGpuPassDepth) {
            open[depth++] = m.pass;
        } else if (!m.begin && depth > 0) {
            --depth;
        }
    }
    for (int pass = 0; pass < num_passes_; ++pass) nanoseconds_[pass] += frame_nanoseconds_[pass];
    if (listener_) {
        listener_->gpu_frame_timed(
            slot.serial,
            std::span<const uint64_t>(frame_nanoseconds_.data(), static_cast<size_t>(num_passes_)));
    }
}

void GpuPassTimers::finish() {
    if (!active_) return;
    if (in_frame_) end_frame();
    // Oldest first, so a stall waits only as long as needed.
    for (int i = 1; i <= kGpuTimerFramesInFlight; ++i) {
        FrameSlot& slot = slots_[(slot_ + i) % kGpuTimerFramesInFlight];
        if (slot.pending) collect(slot);
    }
}

void GpuPassTimers::reset() {
    for (FrameSlot& slot : slots_) slot.pending = false;
    slots_[slot_].count = 0;
    nanoseconds_.fill(0);
    counts_.fill(0);
    frames_ = 0;
    depth_ = 0;
    excess_depth_ = 0;
    diagnostics_ = GpuTimerDiagnostics{};
}

int GpuPassTimers::find_pass(std::string_view name) const {
    for (int i = 0; i < num_passes_; ++i) {
        if (name == names_[i].data()) return i;
    }
    return -1;
}

int GpuPassTimers::find_or_add_pass(std::string_view name) {
    if (int found = find_pass(name); found >= 0) return found;
    if (name.empty() || name.size() > kMaxGpuPassNameLength || num_passes_ == kMaxGpuPasses) {
        return -1;
    }
    auto& slot = names_[num_passes_];
    std::copy(name.begin(), name.end(), slot.begin());
    slot[name.size()] = '\0';
    return num_passes_++;
}

std::vector<GpuPassTotals> GpuPassTimers::totals() const {
    std::vector<GpuPassTotals> out;
    out.reserve(static_cast<size_t>(num_passes_));
    for (int i = 0; i < num_passes_; ++i) {
        double ms = static_cast<double>(nanoseconds_[i]) / 1e6;
        double per_frame = frames_ > 0 ? ms / static_cast<double>(frames_) : 0.0;
        out.push_back(GpuPassTotals{names_[i].data(), ms, per_frame, counts_[i]});
    }
    return out;
}

uint64_t GpuPassTimers::total_nanoseconds(std::string_view name) const {
    int pass = find_pass(name);
    return pass >= 0 ? nanoseconds_[pass] : 0;
}

uint64_t GpuPassTimers::pass_count(std::string_view name) const {
    int pass = find_pass(name);
    return pass >= 0 ? counts_[pass] : 0;
}

}  // namespace nq
