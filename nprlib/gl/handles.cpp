#include "gl/handles.h"

namespace nq::npr::gl {

GLuint generate_name(ObjectKind kind) {
    GLuint id = 0;
    switch (kind) {
        case ObjectKind::buffer:
            glGenBuffers(1, &id);
            break;
        case ObjectKind::vertex_array:
            glGenVertexArrays(1, &id);
            break;
        case ObjectKind::texture:
            glGenTextures(1, &id);
            break;
        case ObjectKind::framebuffer:
            glGenFramebuffers(1, &id);
            break;
        case ObjectKind::program:
            id = glCreateProgram();
            break;
        case ObjectKind::query:
            glGenQueries(1, &id);
            break;
        case ObjectKind::shader:  // needs a stage: glCreateShader(stage) + adopt
        case ObjectKind::sync:    // GLsync is a pointer, owned by StreamBuffer
        case ObjectKind::count:
            break;
    }
    return id;
}

void delete_name(ObjectKind kind, GLuint id) {
    switch (kind) {
        case ObjectKind::buffer:
            glDeleteBuffers(1, &id);
            break;
        case ObjectKind::vertex_array:
            glDeleteVertexArrays(1, &id);
            break;
        case ObjectKind::texture:
            glDeleteTextures(1, &id);
            break;
        case ObjectKind::framebuffer:
            glDeleteFramebuffers(1, &id);
            break;
        case ObjectKind::shader:
            glDeleteShader(id);
            break;
        case ObjectKind::program:
            glDeleteProgram(id);
            break;
        case ObjectKind::query:
            glDeleteQueries(1, &id);
            break;
        case ObjectKind::sync:
        case ObjectKind::count:
            break;
    }
}

}  // namespace nq::npr::gl
