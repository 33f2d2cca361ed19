#include "client/client_state.h"

#include <algorithm>

namespace nq {
namespace {

const ModelInfo kUnknownModel{};

// Beam and explosion models the client draws by name (Quake loads them outside the precache).
constexpr const char* kBoltModel = "progs/bolt.mdl";
constexpr const char* kBolt2Model = "progs/bolt2.mdl";
constexpr const char* kBolt3Model = "progs/bolt3.mdl";
constexpr const char* kBeamModel = "progs/beam.mdl";
constexpr const char* kExplosionModel = "progs/s_explod.spr";

}  // namespace

ClientState::ClientState(const ClientSettings& settings)
    : settings_(settings),
      random_(settings.random_seed),
      particles_(settings.particle_capacity),
      effects_(particles_, random_) {
    style_values_.fill(1.0f);
    model_names_.emplace_back();
    model_info_.emplace_back();
}

void ClientState::clear_for_new_level() {
    signon_ = 0;
    disconnected_ = false;
    level_ = {};
    model_names_.assign(1, std::string());
    precache_models_ = 1;
    client_models_ = {};
    sound_names_.assign(1, std::string());
    sound_events_.clear();
    model_info_.assign(1, ModelInfo{});
    time_ = old_time_ = 0;
    message_times_ = {};
    lerp_fraction_ = 1;
    view_entity_ = 0;
    entities_.clear();
    statics_.clear();
    view_model_anim_ = {};
    player_ = {};
    scoreboard_.clear();
    intermission_ = Intermission::None;
    completed_time_ = 0;
    paused_ = false;
    flashes_.clear();
    skybox_.clear();
    fog_ = {};
    particles_.clear();
    dlights_.clear();
    beams_.clear();
    temp_entities_.clear();
    explosions_.fill(ExplosionSprite{});
    light_styles_.clear();
    style_values_.fill(1.0f);
}

void ClientState::add_client_models() {
    auto index_of = [this](const char* name) {
        auto it = std::find(model_names_.begin(), model_names_.end(), name);
        if (it != model_names_.end()) return static_cast<int>(it - model_names_.begin());
        model_names_.emplace_back(name);
        return static_cast<int>(model_names_.size() - 1);
    };
    client_models_.bolt = index_of(kBoltModel);
    client_models_.bolt2 = index_of(kBolt2Model);
    client_models_.bolt3 = index_of(kBolt3Model);
    client_models_.beam = index_of(kBeamModel);
    client_models_.explosion = index_of(kExplosionModel);
    model_info_.assign(model_names_.size(), ModelInfo{});
}

ClientEntity* ClientState::entity_slot(int number) {
    if (number < 0 || number >= kMaxClientEntities) return nullptr;
    if (static_cast<size_t>(number) >= entities_.size()) {
        entities_.resize(static_cast<size_t>(number) + 1);
    }
    return &entities_[static_cast<size_t>(number)];
}

const ClientEntity* ClientState::entity(int number) const {
    if (number < 0 || static_cast<size_t>(number) >= entities_.size()) return nullptr;
    return &entities_[static_cast<size_t>(number)];
}

void ClientState::set_model_info(std::vector<ModelInfo> info) {
    model_info_ = std::move(info);
    if (model_info_.size() < model_names_.size()) model_info_.resize(model_names_.size());
}

const ModelInfo& ClientState::model_info(int index) const {
    if (index < 0 || static_cast<size_t>(index) >= model_info_.size()) return kUnknownModel;
    return model_info_[static_cast<size_t>(index)];
}

void ClientState::advance_clock(double frame_time) {
    old_time_ = time_;
    time_ += std::max(0.0, frame_time);
}

void ClientState::set_time(double time) {
    old_time_ = time_;
    time_ = time;
}

void ClientState::receive_block_angles(const Vec3& angles) {
    player_.block_view_angles[1] = player_.block_view_angles[0];
    player_.block_view_angles[0] = angles;
}

uint32_t ClientState::message_count(int kind) const {
    if (kind < 0 || static_cast<size_t>(kind) >= message_counts_.size()) return 0;
    return message_counts_[static_cast<size_t>(kind)];
}

void ClientState::warn(std::string text) {
    constexpr size_t kMaxWarnings = 100;  // a broken demo must not grow this without end
    if (warnings_.size() < kMaxWarnings) warnings_.push_back(std::move(text));
}

}  // namespace nq
