// The human-readable table of `mdltool info`.
#include <cstdio>
#include <string>

#include "info_report.h"

namespace nq::mdltool {

namespace {

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

std::string vec3(const Vec3& v) {
    return number(v[0]) + " " + number(v[1]) + " " + number(v[2]);
}

std::string join(const std::vector<std::string>& items, const char* separator) {
    std::string out;
    for (size_t i = 0; i < items.size(); ++i) out += (i ? separator : "") + items[i];
    return out;
}

std::string index_label(size_t index) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "    %4zu  ", index);
    return buf;
}

void row(std::ostream& out, const char* label, const std::string& value) {
    char buf[24];
    std::snprintf(buf, sizeof buf, "  %-12s", label);
    out << buf << value << "\n";
}

std::string flags_text(int32_t flags) {
    auto names = mdl_flag_names(flags);
    return std::to_string(flags) + (names.empty() ? " (none)" : " (" + join(names, ", ") + ")");
}

std::string intervals_text(const std::vector<float>& intervals) {
    std::vector<std::string> parts;
    for (float f : intervals) parts.push_back(number(f));
    return join(parts, " ");
}

void print_skins(std::ostream& out, const Mdl& mdl) {
    const MdlHeader& h = mdl.header;
    row(out, "skins",
        std::to_string(mdl.skins.size()) + " of " + std::to_string(h.skin_width) + "x" +
            std::to_string(h.skin_height));
    for (size_t i = 0; i < mdl.skins.size(); ++i) {
        const MdlSkin& s = mdl.skins[i];
        out << index_label(i)
            << (s.is_group ? "group of " + std::to_string(s.images.size()) + ", intervals " +
                                 intervals_text(s.intervals)
                           : std::string("single"))
            << "\n";
    }
}

size_t count_poses(const Mdl& mdl) {
    size_t poses = 0;
    for (const MdlFrame& f : mdl.frames) poses += f.poses.size();
    return poses;
}

void print_frames(std::ostream& out, const Mdl& mdl) {
    row(out, "frames",
        std::to_string(mdl.frames.size()) + " (" + std::to_string(count_poses(mdl)) + " poses)");
    for (size_t i = 0; i < mdl.frames.size(); ++i) {
        const MdlFrame& f = mdl.frames[i];
        out << index_label(i);
        if (!f.is_group) {
            out << f.poses[0].name << "\n";
            continue;
        }
        std::vector<std::string> parts;
        for (size_t k = 0; k < f.poses.size(); ++k) {
            parts.push_back(f.poses[k].name + " @" + number(f.intervals[k]));
        }
        out << "group of " << f.poses.size() << ": " << join(parts, ", ") << "\n";
    }
}

}  // namespace

void print_info_text(std::ostream& out, const std::string& path, const Mdl& mdl) {
    const MdlHeader& h = mdl.header;
    const Bounds bounds = decoded_frame_bounds(mdl);
    out << path << "\n";
    row(out, "version", std::to_string(h.version));
    row(out, "scale", vec3(h.scale));
    row(out, "origin", vec3(h.scale_origin));
    row(out, "radius", number(h.bounding_radius));
    row(out, "eye", vec3(h.eye_position));
    row(out, "flags", flags_text(h.flags));
    row(out, "sync",
        std::string(sync_type_name(h.sync_type)) + " (" + std::to_string(h.sync_type) + ")");
    print_skins(out, mdl);
    row(out, "vertices", std::to_string(mdl.tex_coords.size()));
    row(out, "triangles", std::to_string(mdl.triangles.size()));
    print_frames(out, mdl);
    row(out, "bbox", "(" + vec3(bounds.min) + ") .. (" + vec3(bounds.max) + ")");
    row(out, "warnings", mdl.warnings.empty() ? "none" : std::to_string(mdl.warnings.size()));
    for (const std::string& w : mdl.warnings) out << "    - " << w << "\n";
    out << "\n";
}

}  // namespace nq::mdltool
