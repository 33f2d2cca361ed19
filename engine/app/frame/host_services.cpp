#include "app/frame/host_services.h"

#include <algorithm>
#include <chrono>

#include "fs/vfs.h"
#include "video/gpu_pass_timers.h"

namespace nq {

HostServices::HostServices(HostServicesWiring wiring)
    : wiring_(std::move(wiring)), plugin_commands_(wiring_.host->commands()) {
    for (int i = 0; i < 256; ++i) {
        palette_[i * 3] = palette_[i * 3 + 1] = palette_[i * 3 + 2] = static_cast<uint8_t>(i);
    }
    for (int level = 0; level < 64; ++level) {
        for (int i = 0; i < 256; ++i) colormap_[level * 256 + i] = static_cast<uint8_t>(i);
    }
}

void HostServices::set_palette(const uint8_t (&rgb)[768]) {
    std::copy(std::begin(rgb), std::end(rgb), palette_.begin());
}

void HostServices::set_colormap(const uint8_t* table, size_t size) {
    std::copy_n(table, std::min(size, colormap_.size()), colormap_.begin());
}

void HostServices::log(int level, std::string_view text) {
    if (wiring_.log) wiring_.log(level, text);
}

const nqr_cvar* HostServices::register_cvar(OwnerId owner, const char* name,
                                            const char* default_value, uint32_t flags,
                                            const char* description) {
    CvarSpec spec;
    spec.name = name;
    spec.default_value = default_value;
    spec.description = description;
    spec.flags = kCvarPlugin;
    if (flags & NQR_CVAR_ARCHIVE) spec.flags |= kCvarArchive;
    if (flags & NQR_CVAR_READONLY) spec.flags |= kCvarReadOnly;
    Cvar* cvar = wiring_.host->cvars().register_cvar(spec, owner);
    return cvar ? cvar->value_ptr() : nullptr;
}

void HostServices::set_cvar(const char* name, const char* value) {
    wiring_.host->cvars().set(name, value, CvarSource::kEngine);
}

bool HostServices::register_command(OwnerId owner, const char* name, nqr_command_fn fn, void* user,
                                    const char* description) {
    return plugin_commands_.add(owner, name, fn, user, description);
}

void HostServices::release_owner(OwnerId owner) {
    plugin_commands_.release_owner(owner);
    wiring_.host->release_owner(owner);
}

bool HostServices::read_file(const char* path, std::vector<uint8_t>& out) {
    if (!wiring_.vfs) return false;
    auto bytes = wiring_.vfs->read(path);
    if (!bytes) return false;
    out = std::move(bytes.value());
    return true;
}

void* HostServices::gl_proc_address(const char* name) {
    return wiring_.gl_proc_address ? wiring_.gl_proc_address(name) : nullptr;
}

double HostServices::real_time() {
    using Clock = std::chrono::steady_clock;
    static const Clock::time_point start = Clock::now();
    return std::chrono::duration<double>(Clock::now() - start).count();
}

void HostServices::trace(const float start[3], const float end[3], nqr_trace* out) {
    if (wiring_.trace) wiring_.trace(start, end, out);
}

void HostServices::gpu_pass_begin(const char* name) {
    if (wiring_.gpu_timers) wiring_.gpu_timers->begin(name);
}

void HostServices::gpu_pass_end() {
    if (wiring_.gpu_timers) wiring_.gpu_timers->end();
}

}  // namespace nq
