// Applying decoded server messages to the client state: dispatch, level setup and the
// player's own data. Entity messages are in entity_messages.cpp, effects in temp_entities.cpp.
#include <algorithm>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>

#include "client/client_state.h"

namespace nq {
namespace {

template <class T, class... Ts>
constexpr bool is_one_of = (std::is_same_v<T, Ts> || ...);

// Whether `text` (console commands, separated by newlines or ';') holds the command "bf".
bool has_bonus_flash_command(std::string_view text) {
    constexpr std::string_view kBonusFlashCommand = "bf";
    constexpr std::string_view kSeparators = "\n;";
    constexpr std::string_view kBlanks = " \t\r";
    while (!text.empty()) {
        size_t end = std::min(text.find_first_of(kSeparators), text.size());
        std::string_view command = text.substr(0, end);
        size_t first = command.find_first_not_of(kBlanks);
        if (first != std::string_view::npos) {
            command = command.substr(first, command.find_last_not_of(kBlanks) - first + 1);
            if (command == kBonusFlashCommand) return true;
        }
        text.remove_prefix(std::min(end + 1, text.size()));
    }
    return false;
}

std::string describe_index(const char* message, const char* what, int value, int limit) {
    return std::string(message) + ": " + what + " " + std::to_string(value) + " outside 0.." +
           std::to_string(limit - 1);
}

}  // namespace

std::optional<std::string> ClientState::apply(const ServerMessage& message) {
    ++message_counts_[static_cast<size_t>(message_kind(message)) & 255u];
    return std::visit(
        [this](const auto& m) -> std::optional<std::string> {
            using T = std::decay_t<decltype(m)>;
            if constexpr (std::is_same_v<T, svc::EntityUpdate>) {
                return on_entity_update(m);
            } else if constexpr (std::is_same_v<T, svc::Time>) {
                message_times_[1] = message_times_[0];
                message_times_[0] = m.time;
            } else if constexpr (std::is_same_v<T, svc::ClientData>) {
                on_client_data(m);
            } else if constexpr (std::is_same_v<T, svc::ServerInfo>) {
                return on_server_info(m);
            } else if constexpr (std::is_same_v<T, svc::SignonNum>) {
                return on_signon(m.stage);
            } else if constexpr (std::is_same_v<T, svc::SpawnBaseline>) {
                return on_baseline(m.entity, m.state, false);
            } else if constexpr (std::is_same_v<T, svc::SpawnBaseline2>) {
                return on_baseline(m.entity, m.state, (m.flags & protocol::B_ALPHA) != 0);
            } else if constexpr (is_one_of<T, svc::SpawnStatic, svc::SpawnStatic2>) {
                return on_static(m.state);
            } else if constexpr (std::is_same_v<T, svc::TempEntity>) {
                return on_temp_entity(m);
            } else if constexpr (std::is_same_v<T, svc::Particle>) {
                on_particle(m);
            } else if constexpr (std::is_same_v<T, svc::LightStyle>) {
                return on_light_style(m);
            } else if constexpr (std::is_same_v<T, svc::UpdateStat>) {
                return on_stat(m);
            } else if constexpr (std::is_same_v<T, svc::UpdateName>) {
                ScoreboardEntry* s = score_entry(m.client);
                if (!s)
                    return describe_index("svc_updatename", "client", m.client, level_.max_clients);
                s->name = m.name;
            } else if constexpr (std::is_same_v<T, svc::UpdateFrags>) {
                ScoreboardEntry* s = score_entry(m.client);
                if (!s)
                    return describe_index("svc_updatefrags", "client", m.client,
                                          level_.max_clients);
                s->frags = m.frags;
            } else if constexpr (std::is_same_v<T, svc::UpdateColors>) {
                ScoreboardEntry* s = score_entry(m.client);
                if (!s)
                    return describe_index("svc_updatecolors", "client", m.client,
                                          level_.max_clients);
                s->colors = m.colors;
            } else if constexpr (std::is_same_v<T, svc::SetView>) {
                view_entity_ = m.entity;
            } else if constexpr (std::is_same_v<T, svc::SetAngle>) {
                player_.set_angles = m.angles;
            } else if constexpr (std::is_same_v<T, svc::Version>) {
                level_.protocol = m.protocol;
            } else if constexpr (std::is_same_v<T, svc::Disconnect>) {
                disconnected_ = true;
            } else if constexpr (std::is_same_v<T, svc::Print>) {
                console_text_.push_back(m.text);
            } else if constexpr (std::is_same_v<T, svc::CenterPrint>) {
                center_prints_.push_back(m.text);
            } else if constexpr (std::is_same_v<T, svc::StuffText>) {
                on_stuff_text(m.text);
            } else if constexpr (std::is_same_v<T, svc::Damage>) {
                flashes_.damage(m.armor, m.blood, time_);
            } else if constexpr (std::is_same_v<T, svc::SetPause>) {
                paused_ = m.paused != 0;
            } else if constexpr (std::is_same_v<T, svc::KilledMonster>) {
                ++player_.stats[kStatMonsters];
            } else if constexpr (std::is_same_v<T, svc::FoundSecret>) {
                ++player_.stats[kStatSecrets];
            } else if constexpr (std::is_same_v<T, svc::Intermission>) {
                on_intermission(Intermission::Intermission, nullptr);
            } else if constexpr (std::is_same_v<T, svc::Finale>) {
                on_intermission(Intermission::Finale, &m.text);
            } else if constexpr (std::is_same_v<T, svc::Cutscene>) {
                on_intermission(Intermission::Cutscene, &m.text);
            } else if constexpr (std::is_same_v<T, svc::Skybox>) {
                skybox_ = m.name;
            } else if constexpr (std::is_same_v<T, svc::Fog>) {
                fog_ = m;
            } else if constexpr (std::is_same_v<T, svc::Sound>) {
                sound_events_.push({SoundEvent::Kind::Start, m.entity, m.channel, m.sound,
                                    float(m.volume) / 255.0f, m.attenuation, m.origin});
            } else if constexpr (std::is_same_v<T, svc::StopSound>) {
                sound_events_.push({SoundEvent::Kind::Stop, m.entity, m.channel, 0, 0, 0, {}});
            } else if constexpr (is_one_of<T, svc::SpawnStaticSound, svc::SpawnStaticSound2>) {
                sound_events_.push({SoundEvent::Kind::Static, 0, 0, m.fields.sound,
                                    float(m.fields.volume), m.fields.attenuation, m.fields.origin});
            } else if constexpr (std::is_same_v<T, svc::CdTrack>) {
                cd_track_ = m.track;
                ++cd_track_messages_;
            }
            // The sell screen and nops change nothing the client draws: they are only counted.
            return std::nullopt;
        },
        message);
}

std::optional<std::string> ClientState::on_server_info(const svc::ServerInfo& m) {
    if (m.max_clients < 1 || m.max_clients > kMaxScoreboard) {
        return "svc_serverinfo: max clients " + std::to_string(m.max_clients) + " outside 1.." +
               std::to_string(kMaxScoreboard);
    }
    clear_for_new_level();  // a new level, also mid-demo: a new connection from scratch
    ++generation_;
    level_ = {m.protocol, m.protocol_flags, m.max_clients, m.game_type, m.level_name};
    model_names_.insert(model_names_.end(), m.models.begin(), m.models.end());
    precache_models_ = model_names_.size();
    sound_names_.insert(sound_names_.end(), m.sounds.begin(), m.sounds.end());
    add_client_models();
    scoreboard_.assign(static_cast<size_t>(m.max_clients), ScoreboardEntry{});
    return std::nullopt;
}

void ClientState::on_client_data(const svc::ClientData& m) {
    PlayerState& p = player_;
    p.view_height = m.view_height;
    p.ideal_pitch = m.ideal_pitch;
    for (int i = 0; i < 3; ++i) p.punch_angles[i] = static_cast<float>(m.punch_angle[i]);
    p.message_velocity[1] = p.message_velocity[0];
    for (int i = 0; i < 3; ++i) p.message_velocity[0][i] = static_cast<float>(m.velocity[i]);
    for (int bit = 0; bit < kItemBits; ++bit) {
        uint32_t mask = uint32_t{1} << bit;
        bool picked_up = (static_cast<uint32_t>(m.items) & mask) != 0 &&
                         (static_cast<uint32_t>(p.items) & mask) == 0;
        if (picked_up) p.item_times[static_cast<size_t>(bit)] = time_;
    }
    p.items = m.items;
    p.on_ground = m.on_ground();
    p.in_water = m.in_water();
    p.weapon_alpha = m.weapon_alpha;
    if (p.stats[kStatWeapon] != m.weapon) view_model_anim_.reset = true;  // no blend across models
    p.stats[kStatWeapon] = m.weapon;
    p.stats[kStatWeaponFrame] = m.weapon_frame;
    p.stats[kStatArmor] = m.armor;
    p.stats[kStatHealth] = m.health;
    p.stats[kStatAmmo] = m.ammo;
    p.stats[kStatShells] = m.shells;
    p.stats[kStatNails] = m.nails;
    p.stats[kStatRockets] = m.rockets;
    p.stats[kStatCells] = m.cells;
    p.stats[kStatActiveWeapon] = m.active_weapon;
}

std::optional<std::string> ClientState::on_signon(int stage) {
    // Stages only go up within one connection; a new svc_serverinfo starts again from 0.
    if (stage <= signon_) {
        warn("svc_signonnum " + std::to_string(stage) + " received at stage " +
             std::to_string(signon_));
    }
    signon_ = stage;
    return std::nullopt;
}

std::optional<std::string> ClientState::on_light_style(const svc::LightStyle& m) {
    if (!light_styles_.set(m.style, m.pattern)) {
        return describe_index("svc_lightstyle", "style", m.style, kMaxLightStyles);
    }
    return std::nullopt;
}

std::optional<std::string> ClientState::on_stat(const svc::UpdateStat& m) {
    if (m.stat < 0 || m.stat >= kMaxStats) {
        return describe_index("svc_updatestat", "stat", m.stat, kMaxStats);
    }
    player_.stats[static_cast<size_t>(m.stat)] = m.value;
    return std::nullopt;
}

ScoreboardEntry* ClientState::score_entry(int client) {
    if (client < 0 || static_cast<size_t>(client) >= scoreboard_.size()) return nullptr;
    return &scoreboard_[static_cast<size_t>(client)];
}

void ClientState::on_stuff_text(const std::string& text) {
    // Servers flash the screen on a pickup by stuffing "bf" into the client's console. It is
    // the one stuffed command the client acts on itself: the engine runs none of them.
    if (has_bonus_flash_command(text)) flashes_.bonus(time_);
    stuff_text_.push_back(text);
}

void ClientState::on_intermission(Intermission kind, const std::string* text) {
    intermission_ = kind;
    completed_time_ = time_;
    if (text) center_prints_.push_back(*text);
}

}  // namespace nq
