#include "plugin/service_table.h"

#include <vector>

namespace nq {

namespace {

const ServiceTable& caller(void* context) {
    return *static_cast<const ServiceTable*>(context);
}

void c_log(void* context, int level, const char* text) {
    caller(context).services().log(level, text ? text : "");
}

const nqr_cvar* c_cvar_register(void* context, const char* name, const char* default_value,
                                uint32_t flags, const char* description) {
    if (!name || !default_value) return nullptr;
    const ServiceTable& c = caller(context);
    return c.services().register_cvar(c.owner(), name, default_value, flags,
                                      description ? description : "");
}

void c_cvar_set(void* context, const char* name, const char* value) {
    if (name && value) caller(context).services().set_cvar(name, value);
}

int c_command_register(void* context, const char* name, nqr_command_fn fn, void* user,
                       const char* description) {
    if (!name || !fn) return 0;
    const ServiceTable& c = caller(context);
    return c.services().register_command(c.owner(), name, fn, user, description ? description : "")
               ? 1
               : 0;
}

int c_file_read(void* context, const char* path, nqr_blob* out) {
    if (!path || !out) return -1;
    auto* bytes = new std::vector<uint8_t>();
    if (!caller(context).services().read_file(path, *bytes)) {
        delete bytes;
        *out = nqr_blob{sizeof(nqr_blob), nullptr, 0, nullptr};
        return -1;
    }
    *out = nqr_blob{sizeof(nqr_blob), bytes->data(), bytes->size(), bytes};
    return 0;
}

void c_file_free(void*, nqr_blob* blob) {
    if (!blob) return;
    delete static_cast<std::vector<uint8_t>*>(blob->engine_private);
    *blob = nqr_blob{sizeof(nqr_blob), nullptr, 0, nullptr};
}

void* c_gl_proc_address(void* context, const char* name) {
    return name ? caller(context).services().gl_proc_address(name) : nullptr;
}

double c_real_time(void* context) {
    return caller(context).services().real_time();
}

void c_trace(void* context, const float start[3], const float end[3], nqr_trace* out) {
    if (!out) return;
    *out = nqr_trace{};
    out->size = sizeof(nqr_trace);
    out->fraction = 1.0f;
    if (start && end) caller(context).services().trace(start, end, out);
}

void c_gpu_pass_begin(void* context, const char* name) {
    caller(context).services().gpu_pass_begin(name);
}
void c_gpu_pass_end(void* context) {
    caller(context).services().gpu_pass_end();
}

}  // namespace

ServiceTable::ServiceTable(EngineServices& services, OwnerId owner)
    : services_(services), owner_(owner) {
    table_ = nqr_engine{
        .size = sizeof(nqr_engine),
        .abi_version = NQR_ABI_VERSION,
        .context = this,
        .log = c_log,
        .cvar_register = c_cvar_register,
        .cvar_set = c_cvar_set,
        .command_register = c_command_register,
        .file_read = c_file_read,
        .file_free = c_file_free,
        .gl_get_proc_address = c_gl_proc_address,
        .real_time = c_real_time,
        .trace = c_trace,
        .palette = services.palette(),
        .colormap = services.colormap(),
        .gpu_pass_begin = c_gpu_pass_begin,
        .gpu_pass_end = c_gpu_pass_end,
    };
}

}  // namespace nq
