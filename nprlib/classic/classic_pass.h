// The GL state the classic hooks (and the styles' drawers built on them) start from and leave
// behind: depth test on (GL_LEQUAL), depth writes on, no blending, no face culling, depth range
// 0..1, vertex array 0, program 0; and the pass an alias entity is drawn in.
#pragma once

#include "nqr_renderer.h"

namespace nq::npr::classic {

void begin_classic_pass();
void end_classic_pass();

// The three passes alias models are drawn in, in this order: opaque ones, translucent ones
// (blended, no depth writes), then the view model (squeezed into the near depth range).
enum class AliasPass { opaque = 0, translucent = 1, view_model = 2 };
AliasPass alias_pass_of(const nqr_entity& entity);

}  // namespace nq::npr::classic
