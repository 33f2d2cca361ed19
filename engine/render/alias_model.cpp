#include "render/alias_model.h"

#include <algorithm>
#include <limits>

namespace nq {

namespace {

// Single frames and skins get the default interval; groups keep theirs.
std::vector<float> intervals_or_default(const std::vector<float>& intervals, size_t count) {
    if (intervals.size() == count && count > 0) return intervals;
    std::vector<float> out(std::max<size_t>(count, 1));
    for (size_t i = 0; i < out.size(); ++i) out[i] = kDefaultAnimationInterval * float(i + 1);
    return out;
}

}  // namespace

std::shared_ptr<const AliasModelData> AliasModelData::build(Mdl mdl) {
    std::shared_ptr<AliasModelData> data(new AliasModelData());
    data->mdl_ = std::move(mdl);
    data->convert_geometry();
    data->convert_frames();
    data->convert_skins();
    data->compute_bounds();
    data->link_abi();
    return data;
}

void AliasModelData::convert_geometry() {
    st_.reserve(mdl_.tex_coords.size() * 3);
    for (const MdlTexCoord& c : mdl_.tex_coords) st_.insert(st_.end(), {c.on_seam, c.s, c.t});
    triangles_.reserve(mdl_.triangles.size() * 4);
    for (const MdlTriangle& t : mdl_.triangles) {
        triangles_.insert(triangles_.end(),
                          {t.faces_front, t.vertices[0], t.vertices[1], t.vertices[2]});
    }
}

void AliasModelData::convert_frames() {
    const size_t num_vertices = mdl_.tex_coords.size();  // = num_verts (checked by the parser)
    uint32_t pose_count = 0;
    for (const MdlFrame& frame : mdl_.frames) {
        nqr_alias_frame f{};
        f.size = sizeof(nqr_alias_frame);
        f.first_pose = pose_count;
        f.num_poses = static_cast<uint32_t>(frame.poses.size());
        pose_count += f.num_poses;
        for (const MdlPose& pose : frame.poses) {
            for (size_t v = 0; v < num_vertices; ++v) {
                // The parser gives every pose num_verts vertices; a short one would shift
                // every later pose, so pad rather than trust it.
                const TriVertex tv = v < pose.vertices.size() ? pose.vertices[v] : TriVertex{};
                poses_.push_back({{tv.v[0], tv.v[1], tv.v[2]}, tv.light_normal_index});
            }
        }
        frame_intervals_.push_back(intervals_or_default(frame.intervals, frame.poses.size()));
        frames_.push_back(f);
    }
    for (size_t i = 0; i < frames_.size(); ++i) {
        const MdlFrame& frame = mdl_.frames[i];
        frames_[i].name = frame.poses.empty() ? "" : frame.poses.front().name.c_str();
        frames_[i].intervals = frame_intervals_[i].data();
    }
}

void AliasModelData::convert_skins() {
    for (const MdlSkin& skin : mdl_.skins) {
        std::vector<const uint8_t*> images;
        for (const auto& image : skin.images) images.push_back(image.data());
        skin_images_.push_back(std::move(images));
        skin_intervals_.push_back(intervals_or_default(skin.intervals, skin.images.size()));
    }
    for (size_t i = 0; i < skin_images_.size(); ++i) {
        nqr_alias_skin s{};
        s.size = sizeof(nqr_alias_skin);
        s.num_images = static_cast<uint32_t>(skin_images_[i].size());
        s.images = skin_images_[i].empty() ? nullptr : skin_images_[i].data();
        s.intervals = skin_intervals_[i].data();
        skins_.push_back(s);
    }
}

void AliasModelData::compute_bounds() {
    const MdlHeader& h = mdl_.header;
    const size_t per_pose = std::max<size_t>(mdl_.tex_coords.size(), 1);
    constexpr glm::vec3 kEmptyMin(std::numeric_limits<float>::max());
    constexpr glm::vec3 kEmptyMax(std::numeric_limits<float>::lowest());
    PoseBounds all{kEmptyMin, kEmptyMax};
    for (size_t first = 0; first < poses_.size(); first += per_pose) {
        PoseBounds pose{kEmptyMin, kEmptyMax};
        for (size_t i = first; i < std::min(first + per_pose, poses_.size()); ++i) {
            glm::vec3 p;
            for (int k = 0; k < 3; ++k) p[k] = h.scale[k] * poses_[i].v[k] + h.scale_origin[k];
            pose.mins = glm::min(pose.mins, p);
            pose.maxs = glm::max(pose.maxs, p);
            radius_ = std::max(radius_, glm::length(p));
        }
        pose_bounds_.push_back(pose);
        all.mins = glm::min(all.mins, pose.mins);
        all.maxs = glm::max(all.maxs, pose.maxs);
    }
    if (poses_.empty()) all = PoseBounds{};
    mins_ = all.mins;
    maxs_ = all.maxs;
}

AliasModelData::PoseBounds AliasModelData::pose_bounds(uint32_t pose) const {
    return pose < pose_bounds_.size() ? pose_bounds_[pose] : PoseBounds{mins_, maxs_};
}

void AliasModelData::link_abi() {
    const MdlHeader& h = mdl_.header;
    alias_ = nqr_alias_model{};
    alias_.size = sizeof(nqr_alias_model);
    for (int i = 0; i < 3; ++i) {
        alias_.scale[i] = h.scale[i];
        alias_.origin[i] = h.scale_origin[i];
    }
    alias_.skin_width = h.skin_width;
    alias_.skin_height = h.skin_height;
    alias_.num_vertices = static_cast<uint32_t>(mdl_.tex_coords.size());
    alias_.num_triangles = static_cast<uint32_t>(mdl_.triangles.size());
    alias_.num_poses = frames_.empty() ? 0 : frames_.back().first_pose + frames_.back().num_poses;
    alias_.num_frames = static_cast<uint32_t>(frames_.size());
    alias_.num_skins = static_cast<uint32_t>(skins_.size());
    alias_.flags = static_cast<uint32_t>(h.flags);
    alias_.st = st_.empty() ? nullptr : st_.data();
    alias_.triangles = triangles_.empty() ? nullptr : triangles_.data();
    alias_.poses = poses_.empty() ? nullptr : poses_.data();
    alias_.frames = frames_.empty() ? nullptr : frames_.data();
    alias_.skins = skins_.empty() ? nullptr : skins_.data();
}

}  // namespace nq
