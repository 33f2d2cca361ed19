// Entity messages: baselines, static entities and fast updates, which send only what differs
// from the entity's baseline (every field not sent takes its baseline value).
#include <string>

#include "client/client_state.h"

namespace nq {
namespace {

using namespace protocol;

std::string entity_range_error(const char* message, int number) {
    return std::string(message) + ": entity " + std::to_string(number) + " outside 0.." +
           std::to_string(kMaxClientEntities - 1);
}

// A 16-bit field sent as a low byte (`low_bit`) and an optional high byte (`high_bit`); the
// parts not sent come from the baseline.
int split_field(const svc::EntityUpdate& m, int sent, int baseline, uint32_t low_bit,
                uint32_t high_bit) {
    int value = m.has(low_bit) ? (sent & 0xFF) : baseline;
    if (m.has(high_bit)) value = (value & 0xFF) | (sent & 0xFF00);
    return value;
}

}  // namespace

std::optional<std::string> ClientState::check_model_index(int model) const {
    if (model >= 0 && static_cast<size_t>(model) < precache_models_) return std::nullopt;
    return "model index " + std::to_string(model) + " outside the " +
           std::to_string(precache_models_ - 1) + " precached models";
}

std::optional<std::string> ClientState::on_baseline(int number, const EntityState& state,
                                                    bool has_alpha) {
    if (number < 0 || number >= kMaxClientEntities) {
        return entity_range_error("svc_spawnbaseline", number);
    }
    if (auto error = check_model_index(state.model)) return "svc_spawnbaseline: " + *error;
    ClientEntity* e = entity_slot(number);
    e->baseline = state;
    if (!has_alpha) e->baseline.alpha = 0;  // default opacity
    return std::nullopt;
}

std::optional<std::string> ClientState::on_static(const EntityState& state) {
    if (statics_.size() >= kMaxStaticEntities) {
        return "svc_spawnstatic: more than " + std::to_string(kMaxStaticEntities) +
               " static entities";
    }
    if (auto error = check_model_index(state.model)) return "svc_spawnstatic: " + *error;
    StaticEntity s;
    s.state = state;
    s.lerp.frame = s.lerp.previous_frame = state.frame;
    statics_.push_back(s);
    return std::nullopt;
}

void ClientState::change_model(ClientEntity& e, int model) {
    e.model = model;
    e.random_phase = random_.unit();  // used when the model animates out of sync
    e.anim.reset = true;              // never blend across models
    if (model == 0) e.force_link = true;
}

std::optional<std::string> ClientState::on_entity_update(const svc::EntityUpdate& m) {
    if (m.entity < 0 || m.entity >= kMaxClientEntities) {
        return entity_range_error("entity update", m.entity);
    }
    ClientEntity& e = *entity_slot(m.entity);
    const EntityState& base = e.baseline;
    const int model = split_field(m, m.model, base.model, U_MODEL, U_MODEL2);
    if (auto error = check_model_index(model)) {
        return "entity update of " + std::to_string(m.entity) + ": " + *error;
    }
    if (signon_ == kSignonStages - 1) signon_ = kSignonStages;  // the first update completes it

    // Lerp only from an update in the message just before this one.
    bool force_link = e.msg_time != message_times_[1];
    if (e.msg_time + 0.2 < message_times_[0]) e.anim.reset = true;  // missed a think: no blend
    e.msg_time = message_times_[0];

    e.frame = split_field(m, m.frame, base.frame, U_FRAME, U_FRAME2);
    e.colormap = m.has(U_COLORMAP) ? m.colormap : base.colormap;
    e.skin = m.has(U_SKIN) ? m.skin : base.skin;
    e.effects = m.has(U_EFFECTS) ? m.effects : 0;
    e.alpha = m.has(U_ALPHA) ? m.alpha : base.alpha;
    e.scale = m.has(U_SCALE) ? static_cast<float>(m.scale) / 16.0f : 1.0f;
    e.lerp_finish = m.has(U_LERPFINISH) ? e.msg_time + m.lerp_finish : -1.0;

    e.msg_origins[1] = e.msg_origins[0];
    e.msg_angles[1] = e.msg_angles[0];
    const uint32_t origin_bits[3] = {U_ORIGIN1, U_ORIGIN2, U_ORIGIN3};
    const uint32_t angle_bits[3] = {U_ANGLE1, U_ANGLE2, U_ANGLE3};
    for (int i = 0; i < 3; ++i) {
        e.msg_origins[0][i] = m.has(origin_bits[i]) ? m.origin[i] : base.origin[i];
        e.msg_angles[0][i] = m.has(angle_bits[i]) ? m.angles[i] : base.angles[i];
    }
    e.step = m.has(U_NOLERP);
    if (e.step) force_link = true;  // moved in steps by the server: never blended
    if (model != e.model) change_model(e, model);
    if (force_link || e.force_link) {
        e.msg_origins[1] = e.msg_origins[0];
        e.msg_angles[1] = e.msg_angles[0];
        e.origin = e.msg_origins[0];
        e.angles = e.msg_angles[0];
        e.force_link = true;
    }
    return std::nullopt;
}

}  // namespace nq
