// GLSL program building: compile + link with the driver's info log handed back as an error
// string (nothing printed, nothing aborted), and a small uniform-location cache so per-frame
// lookups by name cost a string compare, not a GL call, and never allocate after the first.
#pragma once

#include <epoxy/gl.h>

#include <initializer_list>
#include <string>
#include <vector>

#include "gl/handles.h"

namespace nq::npr::gl {

struct ProgramSource {
    const char* name;  // for error messages, e.g. "classic world"
    const char* vertex;
    const char* fragment;            // may be null for a transform-feedback-only program
    const char* geometry = nullptr;  // optional geometry stage (edge quads, fins)
    // Vertex outputs captured by transform feedback, interleaved in this order.
    const char* const* feedback_varyings = nullptr;
    int feedback_count = 0;
    // A compute program (GL 4.3): this one stage, the others ignored.
    const char* compute = nullptr;
};

struct ProgramBuild;

class Program {
  public:
    Program() = default;

    // Compiles and links; on failure the result has an empty program and an error naming the
    // program, the stage and the driver's info log.
    static ProgramBuild build(const ProgramSource& source, ObjectTracker* tracker);

    GLuint id() const { return name_.id(); }
    explicit operator bool() const { return static_cast<bool>(name_); }
    void use() const { glUseProgram(name_.id()); }

    // Location of a uniform (-1 when the linker dropped or never had it), cached by name (found
    // by pointer first, as callers pass string literals, then by comparing the text).
    GLint location(const char* uniform_name);

    void reset() {
        name_.reset();
        cache_.clear();
    }

  private:
    struct CachedLocation {
        const char* key;  // the pointer first asked with: a call site asks with the same one
        std::string name;
        GLint location;
    };

    ProgramName name_;
    std::vector<CachedLocation> cache_;
};

struct ProgramBuild {
    Program program;
    std::string error;  // empty on success
    bool ok() const { return error.empty(); }
};

// Info logs, trimmed of trailing whitespace.
std::string shader_info_log(GLuint shader);
std::string program_info_log(GLuint program);

// Binds each named sampler uniform of the (linked) program to texture unit = its index.
void bind_sampler_units(Program& program, std::initializer_list<const char*> samplers);

}  // namespace nq::npr::gl
