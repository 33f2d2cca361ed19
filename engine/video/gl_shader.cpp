#include "video/gl_shader.h"

namespace nq {

Result<npr::gl::Program> build_program(const char* vertex_source, const char* fragment_source,
                                       const std::string& name) {
    npr::gl::ProgramBuild built =
        npr::gl::Program::build({name.c_str(), vertex_source, fragment_source}, nullptr);
    if (!built.ok()) {
        // gl::Program names the program first; the Error names it as its file instead.
        const std::string prefix = name + ": ";
        const bool named = built.error.compare(0, prefix.size(), prefix) == 0;
        return Error{name, 0, named ? built.error.substr(prefix.size()) : built.error};
    }
    return std::move(built.program);
}

}  // namespace nq
