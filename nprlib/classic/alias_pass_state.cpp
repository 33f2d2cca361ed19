#include "classic/alias_pass_state.h"

namespace nq::npr::classic {

void begin_alias_face_culling() {
    glEnable(GL_CULL_FACE);
    glFrontFace(GL_CW);
    glCullFace(GL_BACK);
}

void draw_alias_elements(GLsizei index_count, bool translucent) {
    if (translucent) {
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glDepthMask(GL_FALSE);
    }
    glDrawElements(GL_TRIANGLES, index_count, GL_UNSIGNED_INT, nullptr);
    if (translucent) {
        glDisable(GL_BLEND);
        glDepthMask(GL_TRUE);
    }
}

void end_alias_face_pass() {
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    glFrontFace(GL_CCW);
    glDisable(GL_CULL_FACE);
    glBindVertexArray(0);
    glUseProgram(0);
    glActiveTexture(GL_TEXTURE0);
}

}  // namespace nq::npr::classic
