#include "render/light_list_smoother.h"

#include <algorithm>
#include <cmath>

#include "render/light_smoother.h"

namespace nq {

namespace {

bool is_dynamic(uint32_t key) {
    return (key & kDynamicLightKey) != 0;
}

float smoothstep01(float x) {
    x = std::clamp(x, 0.0f, 1.0f);
    return x * x * (3.0f - 2.0f * x);
}

float mean_of(const glm::vec3& c) {
    return (c.r + c.g + c.b) / 3.0f;
}

}  // namespace

LightListSmoother::Tracked* LightListSmoother::find(const LightContribution& light) {
    Tracked* best = nullptr;
    float best_distance = kDynamicLightMatch;
    for (Tracked& t : tracked_) {
        if (!t.used || t.in_set || is_dynamic(t.light.key) != is_dynamic(light.key)) continue;
        if (!is_dynamic(light.key)) {
            if (t.light.key == light.key) return &t;
            continue;
        }
        const float d = glm::length(t.light.position - light.position);
        if (d <= best_distance) {
            best_distance = d;
            best = &t;
        }
    }
    return best;
}

// An unused slot, else the one that shows least (lowest weight, then strength).
LightListSmoother::Tracked* LightListSmoother::free_slot() {
    Tracked* weakest = nullptr;
    for (Tracked& t : tracked_) {
        if (!t.used) return &t;
        if (t.in_set) continue;
        if (!weakest || t.weight * t.light.strength < weakest->weight * weakest->light.strength) {
            weakest = &t;
        }
    }
    return weakest;
}

void LightListSmoother::advance(const LightContributions& sampled, float dt) {
    const float step = dt / kLightFadeSeconds;
    const float follow = 1.0f - std::exp(-dt / kLightSmoothingSeconds);
    for (Tracked& t : tracked_) t.in_set = false;
    for (int i = 0; i < sampled.count; ++i) {
        const LightContribution& s = sampled.items[i];
        Tracked* t = find(s);
        if (t) {
            t->light.key = s.key;
            t->light.position = s.position;
            t->light.color += (s.color - t->light.color) * follow;
            t->light.strength = mean_of(t->light.color);
        } else if ((t = free_slot()) != nullptr) {
            *t = Tracked{s, 0.0f, false, true};
        } else {
            continue;  // every slot holds a light of this set: cannot happen with 2x slots
        }
        t->in_set = true;
    }
    for (Tracked& t : tracked_) {
        if (!t.used) continue;
        t.weight = std::clamp(t.weight + (t.in_set ? step : -step), 0.0f, 1.0f);
        if (!t.in_set && t.weight <= 0.0f) t = Tracked{};
    }
}

void LightListSmoother::write(EntityLighting& out) const {
    LightContributions shown;
    for (const Tracked& t : tracked_) {
        if (!t.used) continue;
        LightContribution c = t.light;
        c.color *= smoothstep01(t.weight);
        c.strength = mean_of(c.color);
        keep_strongest(shown, c);
    }
    store_lights(shown, out);
}

void LightListSmoother::update(const LightContributions& sampled, float dt, EntityLighting& out) {
    if (!valid_) {
        tracked_ = {};
        for (int i = 0; i < sampled.count && i < kTrackedLights; ++i) {
            tracked_[i] = Tracked{sampled.items[i], 1.0f, true, true};
        }
        valid_ = true;
    } else if (dt > 0.0f) {
        advance(sampled, dt);
    }
    write(out);
}

}  // namespace nq
