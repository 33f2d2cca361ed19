#include "video/gl_context_setup.h"

#include <epoxy/gl.h>

namespace nq {
namespace {

struct GlVersion {
    int major, minor;
};

// Newest first: 4.5 gives DSA and clip control to plugins that want them; 3.3 is the floor.
constexpr GlVersion kCoreVersions[] = {{4, 5}, {3, 3}};

SDL_GLContext try_core_context(SDL_Window* window, GlVersion v) {
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_CORE);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, v.major);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, v.minor);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_FLAGS, SDL_GL_CONTEXT_FORWARD_COMPATIBLE_FLAG);
    return SDL_GL_CreateContext(window);
}

std::string gl_string(GLenum name) {
    const GLubyte* s = glGetString(name);
    return s ? reinterpret_cast<const char*>(s) : "";
}

}  // namespace

void request_framebuffer_attributes() {
    SDL_GL_SetAttribute(SDL_GL_RED_SIZE, 8);
    SDL_GL_SetAttribute(SDL_GL_GREEN_SIZE, 8);
    SDL_GL_SetAttribute(SDL_GL_BLUE_SIZE, 8);
    SDL_GL_SetAttribute(SDL_GL_DEPTH_SIZE, 24);
    SDL_GL_SetAttribute(SDL_GL_STENCIL_SIZE, 8);
    SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
}

std::string create_core_context(SDL_Window* window, SDL_GLContext* out) {
    std::string failures;
    for (GlVersion v : kCoreVersions) {
        if (SDL_GLContext context = try_core_context(window, v)) {
            *out = context;
            return {};
        }
        failures += "\n  OpenGL " + std::to_string(v.major) + "." + std::to_string(v.minor) +
                    " core: " + SDL_GetError();
    }
    return "no OpenGL 3.3 (or newer) core-profile context could be created:" + failures;
}

GlInfo describe_current_context() {
    GlInfo info;
    glGetIntegerv(GL_MAJOR_VERSION, &info.major);
    glGetIntegerv(GL_MINOR_VERSION, &info.minor);
    info.version = gl_string(GL_VERSION);
    info.renderer = gl_string(GL_RENDERER);
    info.vendor = gl_string(GL_VENDOR);
    info.glsl_version = gl_string(GL_SHADING_LANGUAGE_VERSION);
    info.swap_interval = SDL_GL_GetSwapInterval();
    return info;
}

bool gl_context_is_current() {
    return SDL_GL_GetCurrentContext() != nullptr;
}

}  // namespace nq
