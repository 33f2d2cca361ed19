#include "classic/classic_pass.h"

#include <epoxy/gl.h>

#include "abi/abi_access.h"

namespace nq::npr::classic {

void begin_classic_pass() {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_TRUE);
    glDepthRange(0.0, 1.0);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
}

void end_classic_pass() {
    glDepthMask(GL_TRUE);
    glDepthRange(0.0, 1.0);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glBindVertexArray(0);
    glUseProgram(0);
    glActiveTexture(GL_TEXTURE0);
}

AliasPass alias_pass_of(const nqr_entity& entity) {
    if ((entity.flags & NQR_ENTITY_VIEWMODEL) != 0) return AliasPass::view_model;
    return entity_alpha(entity.alpha) < 1.0f ? AliasPass::translucent : AliasPass::opaque;
}

}  // namespace nq::npr::classic
