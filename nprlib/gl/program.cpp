#include "gl/program.h"

#include <array>
#include <cstring>
#include <iterator>
#include <utility>

namespace nq::npr::gl {
namespace {

std::string trimmed(std::string text) {
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ' || text.back() == '\0')) {
        text.pop_back();
    }
    return text;
}

const char* stage_name(GLenum stage) {
    switch (stage) {
        case GL_VERTEX_SHADER:
            return "vertex";
        case GL_GEOMETRY_SHADER:
            return "geometry";
        case GL_FRAGMENT_SHADER:
            return "fragment";
        case GL_COMPUTE_SHADER:
            return "compute";
        default:
            return "?";
    }
}

// Compiles one stage; returns an empty handle and fills `error` on failure.
Shader compile_stage(GLenum stage, const char* text, const char* program_name,
                     ObjectTracker* tracker, std::string& error) {
    Shader shader = Shader::adopt(glCreateShader(stage), tracker);
    if (!shader) {
        error = std::string(program_name) + ": glCreateShader failed";
        return {};
    }
    glShaderSource(shader.id(), 1, &text, nullptr);
    glCompileShader(shader.id());
    GLint compiled = GL_FALSE;
    glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &compiled);
    if (compiled != GL_TRUE) {
        error = std::string(program_name) + ": " + stage_name(stage) +
                " shader failed to compile:\n" + shader_info_log(shader.id());
        return {};
    }
    return shader;
}

}  // namespace

std::string shader_info_log(GLuint shader) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<size_t>(length > 0 ? length : 0), '\0');
    if (length > 0) glGetShaderInfoLog(shader, length, nullptr, log.data());
    return trimmed(std::move(log));
}

std::string program_info_log(GLuint program) {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<size_t>(length > 0 ? length : 0), '\0');
    if (length > 0) glGetProgramInfoLog(program, length, nullptr, log.data());
    return trimmed(std::move(log));
}

ProgramBuild Program::build(const ProgramSource& source, ObjectTracker* tracker) {
    ProgramBuild result;
    const char* name = source.name ? source.name : "program";
    // A compute program has that one stage; any other has a vertex stage and the optional ones.
    const std::pair<GLenum, const char*> stages[] = {
        {GL_VERTEX_SHADER, source.compute ? nullptr : source.vertex},
        {GL_FRAGMENT_SHADER, source.compute ? nullptr : source.fragment},
        {GL_GEOMETRY_SHADER, source.compute ? nullptr : source.geometry},
        {GL_COMPUTE_SHADER, source.compute},
    };
    if (!source.compute && !source.vertex) {
        result.error = std::string(name) + ": no vertex or compute stage";
        return result;
    }
    std::array<Shader, std::size(stages)> shaders;
    for (size_t i = 0; i < std::size(stages); ++i) {
        if (!stages[i].second) continue;
        shaders[i] = compile_stage(stages[i].first, stages[i].second, name, tracker, result.error);
        if (!shaders[i]) return result;
    }

    ProgramName program = ProgramName::create(tracker);
    for (const Shader& shader : shaders) {
        if (shader) glAttachShader(program.id(), shader.id());
    }
    if (source.feedback_count > 0) {
        glTransformFeedbackVaryings(program.id(), source.feedback_count, source.feedback_varyings,
                                    GL_INTERLEAVED_ATTRIBS);
    }
    glLinkProgram(program.id());
    GLint linked = GL_FALSE;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &linked);
    // The shaders are flagged for deletion with the program once detached.
    for (const Shader& shader : shaders) {
        if (shader) glDetachShader(program.id(), shader.id());
    }
    if (linked != GL_TRUE) {
        result.error =
            std::string(name) + ": program failed to link:\n" + program_info_log(program.id());
        return result;
    }
    result.program.name_ = std::move(program);
    return result;
}

GLint Program::location(const char* uniform_name) {
    for (const CachedLocation& cached : cache_) {
        // The same pointer nearly always means the same literal; one compare makes it certain.
        if (cached.key == uniform_name && cached.name == uniform_name) return cached.location;
    }
    for (const CachedLocation& cached : cache_) {
        if (std::strcmp(cached.name.c_str(), uniform_name) == 0) return cached.location;
    }
    GLint location = glGetUniformLocation(name_.id(), uniform_name);
    cache_.push_back({uniform_name, uniform_name, location});
    return location;
}

void bind_sampler_units(Program& program, std::initializer_list<const char*> samplers) {
    program.use();
    GLint unit = 0;
    for (const char* sampler : samplers) {
        glUniform1i(program.location(sampler), unit);
        ++unit;
    }
}

}  // namespace nq::npr::gl
