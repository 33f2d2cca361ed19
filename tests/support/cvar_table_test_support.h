// A stand-in for the engine's cvar registry and the docs/console.md lookup, shared by the tests
// of the styles' cvar tables (technical, illustrative).
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "nqr_renderer.h"
#include "support/build_paths.h"

namespace nq::npr::test {

// A stand-in for the engine's cvar registry: values parsed as the engine does (value = atof,
// integer = atoi of the string).
struct FakeCvars {
    std::map<std::string, nqr_cvar> cvars;
    std::map<std::string, std::string> strings;

    void set(const std::string& name, const std::string& value) {
        strings[name] = value;
        nqr_cvar& c = cvars[name];
        c.size = sizeof(nqr_cvar);
        c.value = static_cast<float>(std::atof(value.c_str()));
        c.integer = std::atoi(value.c_str());
        c.string = strings[name].c_str();
        ++c.modified_count;
    }
};

inline FakeCvars* g_fake = nullptr;

inline const nqr_cvar* fake_register(void*, const char* name, const char* default_value, uint32_t,
                                     const char*) {
    if (!g_fake->cvars.count(name)) g_fake->set(name, default_value);
    return &g_fake->cvars[name];
}

inline nqr_engine fake_engine() {
    nqr_engine engine{};
    engine.size = sizeof(nqr_engine);
    engine.abi_version = NQR_ABI_VERSION;
    engine.cvar_register = fake_register;
    return engine;
}

// docs/console.md, found by walking up from the build's bin directory to the source tree.
inline std::string console_doc() {
    std::filesystem::path dir = std::filesystem::absolute(nq::test::bin_dir());
    for (; !dir.empty() && dir != dir.root_path(); dir = dir.parent_path()) {
        std::ifstream in(dir / "docs" / "console.md");
        if (in) {
            std::stringstream text;
            text << in.rdbuf();
            return text.str();
        }
    }
    return {};
}

}  // namespace nq::npr::test
