// Keeps every shared library loaded right now resident for the life of the process.
//
// Why: SDL unloads the GL driver (Mesa's swrast_dri.so, libLLVM, ...) when video shuts down.
// LeakSanitizer then reports the driver's process-lifetime allocations from an "<unknown
// module>" that cannot be suppressed by name, and a sanitizer build of the engine would exit
// non-zero on every run. Called once the GL context exists (before any renderer plugin is
// loaded, so plugins stay unloadable for hot swap), it hides no leak of our own.
#pragma once

namespace nq {

void keep_loaded_libraries_resident();

}  // namespace nq
