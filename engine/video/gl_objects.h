// Move-only owners of OpenGL object names (buffer, vertex array, texture, framebuffer, shader,
// program). Each deletes its object when it goes, if a GL context is still current: a context
// that is already gone took its objects with it, and calling GL then would be an error.
#pragma once

#include <epoxy/gl.h>

#include <utility>

namespace nq {

// True when the calling thread has a current GL context (the guard in every destructor).
bool gl_context_is_current();

template <class Kind>
class GlObject {
  public:
    GlObject() = default;
    explicit GlObject(GLuint adopted) : id_(adopted) {}
    ~GlObject() { reset(); }

    GlObject(GlObject&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
    GlObject& operator=(GlObject&& other) noexcept {
        if (this != &other) {
            reset();
            id_ = std::exchange(other.id_, 0);
        }
        return *this;
    }
    GlObject(const GlObject&) = delete;
    GlObject& operator=(const GlObject&) = delete;

    // A new object of this kind (glGen*); only for kinds that have Kind::generate.
    static GlObject generate() { return GlObject(Kind::generate()); }

    GLuint id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }
    GLuint release() { return std::exchange(id_, 0); }
    void reset() {
        if (id_ != 0 && gl_context_is_current()) Kind::destroy(id_);
        id_ = 0;
    }

  private:
    GLuint id_ = 0;
};

struct GlBufferKind {
    static GLuint generate();
    static void destroy(GLuint id);
};
struct GlVertexArrayKind {
    static GLuint generate();
    static void destroy(GLuint id);
};
struct GlTextureKind {
    static GLuint generate();
    static void destroy(GLuint id);
};
struct GlFramebufferKind {
    static GLuint generate();
    static void destroy(GLuint id);
};
struct GlShaderKind {  // created by glCreateShader(stage): adopt the name
    static void destroy(GLuint id);
};
struct GlProgramKind {  // created by glCreateProgram: adopt the name
    static void destroy(GLuint id);
};

using GlBuffer = GlObject<GlBufferKind>;
using GlVertexArray = GlObject<GlVertexArrayKind>;
using GlTexture = GlObject<GlTextureKind>;
using GlFramebuffer = GlObject<GlFramebufferKind>;
using GlShader = GlObject<GlShaderKind>;
using GlProgram = GlObject<GlProgramKind>;

}  // namespace nq
