#include "video/resident_libraries.h"

#include <dlfcn.h>
#include <link.h>

namespace nq {

void keep_loaded_libraries_resident() {
    dl_iterate_phdr(
        [](dl_phdr_info* info, size_t, void*) {
            if (info->dlpi_name && info->dlpi_name[0] != '\0') {
                // RTLD_NOLOAD: only takes a reference on what is already loaded.
                dlopen(info->dlpi_name, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
            }
            return 0;
        },
        nullptr);
}

}  // namespace nq
