// The --json form of `mdltool info`: one object per model, stable key names.
#include "info_report.h"

#include <cstdio>
#include <cstdlib>

namespace nq::mdltool {

namespace {

// The shortest decimal that reads back as the same float, so 0.1f prints as 0.1 rather than
// 0.100000001 (JsonWriter prints doubles with 9 significant digits).
double shortest(float f) {
    char buf[32];
    for (int precision = 6; precision < 9; ++precision) {
        std::snprintf(buf, sizeof buf, "%.*g", precision, f);
        if (std::strtof(buf, nullptr) == f) return std::strtod(buf, nullptr);
    }
    return f;
}

void vec3(JsonWriter& json, const char* key, const Vec3& v) {
    json.key(key).begin_array();
    for (float f : v) json.value(shortest(f));
    json.end_array();
}

void floats(JsonWriter& json, const char* key, const std::vector<float>& values) {
    json.key(key).begin_array();
    for (float f : values) json.value(shortest(f));
    json.end_array();
}

void header(JsonWriter& json, const MdlHeader& h) {
    json.field("version", h.version);
    vec3(json, "scale", h.scale);
    vec3(json, "scale_origin", h.scale_origin);
    json.field("bounding_radius", shortest(h.bounding_radius));
    vec3(json, "eye_position", h.eye_position);
    json.field("size", shortest(h.size));
    json.field("flags", h.flags);
    json.key("flag_names").begin_array();
    for (const std::string& name : mdl_flag_names(h.flags)) json.value(name);
    json.end_array();
    json.field("sync_type", h.sync_type);
    json.field("sync_type_name", sync_type_name(h.sync_type));
}

void skins(JsonWriter& json, const Mdl& mdl) {
    json.field("skin_width", mdl.header.skin_width);
    json.field("skin_height", mdl.header.skin_height);
    json.field("num_skins", static_cast<uint64_t>(mdl.skins.size()));
    json.key("skins").begin_array();
    for (const MdlSkin& s : mdl.skins) {
        json.begin_object();
        json.field("group", s.is_group);
        json.field("images", static_cast<uint64_t>(s.images.size()));
        floats(json, "intervals", s.intervals);
        json.end_object();
    }
    json.end_array();
}

void frames(JsonWriter& json, const Mdl& mdl) {
    json.field("num_frames", static_cast<uint64_t>(mdl.frames.size()));
    json.key("frames").begin_array();
    for (const MdlFrame& f : mdl.frames) {
        json.begin_object();
        json.field("group", f.is_group);
        json.key("poses").begin_array();
        for (const MdlPose& p : f.poses) json.value(p.name);
        json.end_array();
        floats(json, "intervals", f.intervals);
        json.end_object();
    }
    json.end_array();
}

}  // namespace

void write_info_json(JsonWriter& json, const std::string& path, const Mdl& mdl) {
    json.begin_object();
    json.field("file", path);
    json.field("ok", true);
    header(json, mdl.header);
    skins(json, mdl);
    json.field("num_verts", static_cast<uint64_t>(mdl.tex_coords.size()));
    json.field("num_tris", static_cast<uint64_t>(mdl.triangles.size()));
    frames(json, mdl);
    const Bounds bounds = decoded_frame_bounds(mdl);
    json.key("bbox").begin_object();
    vec3(json, "min", bounds.min);
    vec3(json, "max", bounds.max);
    json.end_object();
    json.field("trailing_bytes", mdl.trailing_bytes);
    json.key("warnings").begin_array();
    for (const std::string& w : mdl.warnings) json.value(w);
    json.end_array();
    json.end_object();
}

void write_error_json(JsonWriter& json, const std::string& path, const Error& error) {
    json.begin_object();
    json.field("file", path);
    json.field("ok", false);
    json.key("error").begin_object();
    json.field("file", error.file);
    json.field("offset", error.offset);
    json.field("message", error.message);
    json.end_object();
    json.end_object();
}

}  // namespace nq::mdltool
