// One loaded renderer plugin: the shared library, its validated function table and its owner
// id. Loading checks everything the ABI promises before a single hook is trusted.
#pragma once

#include <memory>
#include <string>

#include "common/result.h"
#include "host/owner.h"
#include "nqr_renderer.h"

namespace nq {

class PluginLibrary {
public:
    // dlopen()s `path`, finds NQR_ENTRY_POINT, calls it and validates the returned table
    // (non-NULL, ABI major, size, required hooks, name). Does not call init().
    static Result<std::unique_ptr<PluginLibrary>> open(const std::string& path,
                                                       const nqr_engine* engine, OwnerId owner);
    ~PluginLibrary();  // dlclose()s; the caller must have called shutdown() if init() succeeded

    PluginLibrary(const PluginLibrary&) = delete;
    PluginLibrary& operator=(const PluginLibrary&) = delete;

    // The plugin's table, copied into host memory: fields an older plugin did not have are NULL.
    const nqr_renderer& table() const { return table_; }
    const std::string& name() const { return name_; }
    const std::string& path() const { return path_; }
    OwnerId owner() const { return owner_; }

private:
    PluginLibrary(void* handle, std::string path, OwnerId owner)
        : handle_(handle), path_(std::move(path)), owner_(owner) {}

    void* handle_ = nullptr;
    std::string path_;
    std::string name_;
    OwnerId owner_;
    nqr_renderer table_{};
};

// Checks a table a plugin returned against this engine's ABI; "" when acceptable, otherwise
// the reason (shown to the user).
std::string validate_renderer_table(const nqr_renderer* table);

}  // namespace nq
