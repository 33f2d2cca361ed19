#include "app/frame/scene_framebuffer.h"

#include <epoxy/gl.h>

namespace nq {

namespace {

GLuint make_texture(GLenum internal_format, GLenum format, GLenum type, int w, int h) {
    GLuint tex = 0;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, internal_format, w, h, 0, format, type, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);
    return tex;
}

}  // namespace

SceneFramebuffer::~SceneFramebuffer() {
    release();
}

void SceneFramebuffer::release() {
    GLuint textures[] = {gbuffer_.color_texture, gbuffer_.normal_texture, gbuffer_.depth_texture};
    if (gbuffer_.framebuffer) glDeleteFramebuffers(1, &gbuffer_.framebuffer);
    for (GLuint t : textures) {
        if (t) glDeleteTextures(1, &t);
    }
    gbuffer_ = nqr_gbuffer{sizeof(nqr_gbuffer), 0, 0, 0, 0, 0, 0};
}

bool SceneFramebuffer::prepare(int width, int height) {
    if (gbuffer_.framebuffer && gbuffer_.width == width && gbuffer_.height == height) return true;
    release();
    gbuffer_.width = width;
    gbuffer_.height = height;
    gbuffer_.color_texture = make_texture(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, width, height);
    gbuffer_.normal_texture = make_texture(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, width, height);
    gbuffer_.depth_texture =
        make_texture(GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, width, height);
    glGenFramebuffers(1, &gbuffer_.framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, gbuffer_.framebuffer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D,
                           gbuffer_.color_texture, 0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D,
                           gbuffer_.normal_texture, 0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D,
                           gbuffer_.depth_texture, 0);
    bool complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (!complete) release();
    return complete;
}

void SceneFramebuffer::bind_and_clear() {
    glBindFramebuffer(GL_FRAMEBUFFER, gbuffer_.framebuffer);
    const GLenum outputs[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glDrawBuffers(2, outputs);
    glViewport(0, 0, gbuffer_.width, gbuffer_.height);
    const GLfloat black[] = {0, 0, 0, 1};
    const GLfloat facing_viewer[] = {0.5f, 0.5f, 1.0f, 0.0f};  // encoded (0, 0, 1), alpha 0 = sky
    glClearBufferfv(GL_COLOR, 0, black);
    glClearBufferfv(GL_COLOR, 1, facing_viewer);
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
}

}  // namespace nq
