#include "video/gl_objects.h"

#include <SDL.h>

namespace nq {

bool gl_context_is_current() {
    return SDL_GL_GetCurrentContext() != nullptr;
}

GLuint GlBufferKind::generate() {
    GLuint id = 0;
    glGenBuffers(1, &id);
    return id;
}
void GlBufferKind::destroy(GLuint id) {
    glDeleteBuffers(1, &id);
}

GLuint GlVertexArrayKind::generate() {
    GLuint id = 0;
    glGenVertexArrays(1, &id);
    return id;
}
void GlVertexArrayKind::destroy(GLuint id) {
    glDeleteVertexArrays(1, &id);
}

GLuint GlTextureKind::generate() {
    GLuint id = 0;
    glGenTextures(1, &id);
    return id;
}
void GlTextureKind::destroy(GLuint id) {
    glDeleteTextures(1, &id);
}

GLuint GlFramebufferKind::generate() {
    GLuint id = 0;
    glGenFramebuffers(1, &id);
    return id;
}
void GlFramebufferKind::destroy(GLuint id) {
    glDeleteFramebuffers(1, &id);
}

void GlShaderKind::destroy(GLuint id) {
    glDeleteShader(id);
}

void GlProgramKind::destroy(GLuint id) {
    glDeleteProgram(id);
}

}  // namespace nq
