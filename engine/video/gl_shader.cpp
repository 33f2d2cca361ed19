#include "video/gl_shader.h"

#include <vector>

namespace nq {
namespace {

const char* stage_name(GLenum stage) {
    switch (stage) {
        case GL_VERTEX_SHADER:
            return "vertex";
        case GL_FRAGMENT_SHADER:
            return "fragment";
        case GL_GEOMETRY_SHADER:
            return "geometry";
        case GL_TESS_CONTROL_SHADER:
            return "tessellation control";
        case GL_TESS_EVALUATION_SHADER:
            return "tessellation evaluation";
        case GL_COMPUTE_SHADER:
            return "compute";
        default:
            return "unknown-stage";
    }
}

std::string shader_log(GLuint shader) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    if (length <= 1) return "(the driver gave no log)";
    std::vector<char> log(static_cast<size_t>(length));
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    return std::string(log.data());
}

std::string program_log(GLuint program) {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    if (length <= 1) return "(the driver gave no log)";
    std::vector<char> log(static_cast<size_t>(length));
    glGetProgramInfoLog(program, length, nullptr, log.data());
    return std::string(log.data());
}

}  // namespace

Result<GlShader> compile_shader(GLenum stage, std::string_view source, const std::string& name) {
    GlShader shader(glCreateShader(stage));
    if (!shader) {
        return Error{name, 0, std::string("cannot create a ") + stage_name(stage) + " shader"};
    }
    const GLchar* text = source.data();
    const GLint length = static_cast<GLint>(source.size());
    glShaderSource(shader.id(), 1, &text, &length);
    glCompileShader(shader.id());
    GLint compiled = GL_FALSE;
    glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &compiled);
    if (compiled != GL_TRUE) {
        return Error{name, 0,
                     std::string(stage_name(stage)) + " shader failed to compile:\n" +
                         shader_log(shader.id())};
    }
    return shader;
}

Result<GlProgram> link_program(std::initializer_list<GLuint> shaders, const std::string& name) {
    GlProgram program(glCreateProgram());
    if (!program) return Error{name, 0, "cannot create a program"};
    for (GLuint shader : shaders) glAttachShader(program.id(), shader);
    glLinkProgram(program.id());
    for (GLuint shader : shaders) glDetachShader(program.id(), shader);
    GLint linked = GL_FALSE;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &linked);
    if (linked != GL_TRUE) {
        return Error{name, 0, "program failed to link:\n" + program_log(program.id())};
    }
    return program;
}

Result<GlProgram> build_program(std::string_view vertex_source, std::string_view fragment_source,
                                const std::string& name) {
    auto vertex = compile_shader(GL_VERTEX_SHADER, vertex_source, name);
    if (!vertex) return vertex.error();
    auto fragment = compile_shader(GL_FRAGMENT_SHADER, fragment_source, name);
    if (!fragment) return fragment.error();
    return link_program({vertex->id(), fragment->id()}, name);
}

}  // namespace nq
