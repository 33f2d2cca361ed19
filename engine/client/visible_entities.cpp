#include "client/visible_entities.h"

#include <algorithm>

namespace nq {
namespace {

void set_colors(const ClientState& client, int colormap, VisibleEntity& v) {
    if (colormap < 1 || static_cast<size_t>(colormap) > client.scoreboard().size()) return;
    const int colors = client.scoreboard()[static_cast<size_t>(colormap - 1)].colors;
    v.top_color = static_cast<uint8_t>((colors >> 4) & 15);
    v.bottom_color = static_cast<uint8_t>(colors & 15);
    v.has_translation = true;
}

void set_animation(const ClientState& client, const FrameLerp& lerp, int skin, VisibleEntity& v) {
    const ModelInfo& info = client.model_info(v.model);
    v.frame = lerp.frame;
    v.pose = resolve_frame_blend(info, lerp, client.time());
    v.skin = skin;
    v.skin_image = resolve_skin_image(info, skin, client.time() + lerp.syncbase);
}

void add_server_entities(const ClientState& client, VisibleEntityList& out) {
    for (size_t i = 1; i < client.entity_slots(); ++i) {
        const ClientEntity& e = *client.entity(static_cast<int>(i));
        if (!e.visible || static_cast<int>(i) == client.view_entity()) continue;
        if (e.alpha == kAlphaInvisible) continue;
        VisibleEntity v;
        v.number = static_cast<uint32_t>(i);
        v.model = e.model;
        v.origin = e.origin;
        v.angles = e.angles;
        v.scale = e.scale;
        v.alpha = decode_alpha(e.alpha);
        v.effects = e.effects;
        set_animation(client, e.anim.lerp, e.skin, v);
        set_colors(client, e.colormap, v);
        if (!out.push(v)) return;
    }
}

void add_static_entities(const ClientState& client, uint32_t& number, VisibleEntityList& out) {
    for (const StaticEntity& s : client.static_entities()) {
        const uint32_t n = number++;
        if (s.state.model == 0 || s.state.alpha == kAlphaInvisible) continue;
        VisibleEntity v;
        v.number = n;
        v.model = s.state.model;
        v.flags = kVisibleStatic;
        v.origin = s.state.origin;
        v.angles = s.state.angles;
        v.alpha = decode_alpha(s.state.alpha);
        set_animation(client, s.lerp, s.state.skin, v);
        if (!out.push(v)) return;
    }
}

void add_temp_entities(const ClientState& client, uint32_t& number, VisibleEntityList& out) {
    for (const TempModelEntity& t : client.temp_entities()) {
        VisibleEntity v;
        v.number = number++;
        v.model = t.model;
        v.flags = kVisibleTemp;
        v.origin = t.origin;
        v.angles = t.angles;
        FrameLerp lerp;
        lerp.frame = lerp.previous_frame = t.frame;
        set_animation(client, lerp, 0, v);
        if (!out.push(v)) return;
    }
}

void add_view_model(const ClientState& client, const ViewResult& view, uint32_t number,
                    VisibleEntityList& out) {
    const ViewModelPlacement& gun = view.view_model;
    if (view.intermission || !gun.visible) return;
    VisibleEntity v;
    v.number = number;
    v.model = gun.model;
    v.flags = kVisibleViewModel;
    v.origin = gun.origin;
    v.angles = gun.angles;
    v.alpha = gun.alpha;
    set_animation(client, client.view_model_animation().lerp, 0, v);
    out.push(v);
}

}  // namespace

bool VisibleEntityList::push(const VisibleEntity& e) {
    if (count_ == items_.size()) {
        ++dropped_;
        return false;
    }
    items_[count_++] = e;
    return true;
}

void collect_visible_entities(const ClientState& client, const ViewResult& view,
                              VisibleEntityList& out) {
    out.clear();
    add_server_entities(client, out);
    uint32_t number = static_cast<uint32_t>(std::max<size_t>(client.entity_slots(), 1));
    add_static_entities(client, number, out);
    add_temp_entities(client, number, out);
    add_view_model(client, view, number, out);
}

}  // namespace nq
