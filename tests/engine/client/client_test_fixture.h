// Shared helpers of the client tests: synthetic server messages and a client that has seen a
// serverinfo, and model information read from the real LibreQuake files.
#pragma once

#include <gtest/gtest.h>

#include <span>
#include <string>
#include <vector>

#include "client/client_state.h"
#include "client/model_info.h"
#include "common/file_io.h"
#include "formats/mdl.h"
#include "formats/spr.h"
#include "support/test_data.h"

namespace nq::test {

inline svc::ServerInfo server_info(std::vector<std::string> models, int max_clients = 1) {
    svc::ServerInfo info;
    info.protocol = protocol::kFitzQuake;
    info.max_clients = max_clients;
    info.level_name = "test level";
    info.models = std::move(models);
    return info;
}

// Applies messages one by one, failing the test on the first refusal.
inline void apply_all(ClientState& client, const std::vector<ServerMessage>& messages) {
    for (const ServerMessage& m : messages) {
        auto problem = client.apply(m);
        ASSERT_FALSE(problem.has_value()) << *problem;
    }
}

inline svc::EntityUpdate origin_update(int entity, const Vec3& origin) {
    svc::EntityUpdate u;
    u.bits = protocol::U_SIGNAL | protocol::U_MOREBITS | protocol::U_ORIGIN1 | protocol::U_ORIGIN2 |
             protocol::U_ORIGIN3;
    u.entity = entity;
    u.origin = origin;
    return u;
}

inline svc::SpawnBaseline baseline(int entity, int model, const Vec3& origin) {
    svc::SpawnBaseline b;
    b.entity = entity;
    b.state.model = model;
    b.state.origin = origin;
    return b;
}

// An alias model without data: `frames` single poses, then one group per entry of `groups`
// (each a list of cumulative intervals).
inline ModelInfo alias_info(uint32_t frames, std::vector<std::vector<float>> groups = {},
                            int32_t flags = 0) {
    ModelInfo info;
    info.kind = ModelKind::Alias;
    info.flags = flags;
    info.lerp_poses = true;
    uint32_t pose = 0;
    for (uint32_t i = 0; i < frames; ++i) info.frames.push_back({pose++, 1, {}});
    for (auto& intervals : groups) {
        auto count = static_cast<uint32_t>(intervals.size());
        info.frames.push_back({pose, count, intervals});
        pose += count;
    }
    info.skins.push_back({0, 1, {}});
    return info;
}

// ModelInfo for every model name, read from the LibreQuake game directory; names that are
// brush models get brush info, files that are absent stay unknown (as the data's README says
// some are).
inline std::vector<ModelInfo> load_model_info(std::span<const std::string> names) {
    std::vector<ModelInfo> out(names.size());
    auto ends_with = [](const std::string& s, const char* tail) {
        std::string t(tail);
        return s.size() >= t.size() && s.compare(s.size() - t.size(), t.size(), t) == 0;
    };
    for (size_t i = 0; i < names.size(); ++i) {
        const std::string& name = names[i];
        if (name.empty()) continue;
        if (name[0] == '*' || ends_with(name, ".bsp")) {
            out[i] = brush_model_info();
            continue;
        }
        auto bytes = read_file(lq1_dir() + "/" + name);
        if (!bytes) continue;
        if (ends_with(name, ".mdl")) {
            auto mdl = parse_mdl(bytes.value(), name);
            if (mdl) out[i] = model_info_from_mdl(mdl.value());
        } else if (ends_with(name, ".spr")) {
            auto spr = parse_spr(bytes.value(), name);
            if (spr) out[i] = model_info_from_spr(spr.value());
        }
    }
    return out;
}

inline std::vector<uint8_t> load_lq1(const std::string& file) {
    auto bytes = read_file(lq1_dir() + "/" + file);
    if (!bytes) throw std::runtime_error(bytes.error().to_string());
    return std::move(bytes.value());
}

}  // namespace nq::test
