// An entity's lighting as the engine keeps it: the ABI's nqr_entity_light and the storage its
// light list points into. A value type: a copy's list points at its own sources, so the
// samplers and smoothers pass it around freely and a frame hands plugins a pointer to it.
#pragma once

#include <array>

#include "nqr_renderer.h"

namespace nq {

struct EntityLighting : nqr_entity_light {
    std::array<nqr_light_source, NQR_MAX_ENTITY_LIGHTS> sources{};

    EntityLighting() : nqr_entity_light{} { point_at_sources(); }
    EntityLighting(const EntityLighting& other) : nqr_entity_light(other), sources(other.sources) {
        point_at_sources();
    }
    EntityLighting& operator=(const EntityLighting& other) {
        static_cast<nqr_entity_light&>(*this) = other;
        sources = other.sources;
        point_at_sources();
        return *this;
    }

  private:
    void point_at_sources() {
        size = sizeof(nqr_entity_light);
        lights = sources.data();
    }
};

}  // namespace nq
