#include "adjacency/alias_source.h"

namespace nq::npr::adjacency {

AliasSource::AliasSource(const nqr_alias_model& model) : model_(model) {
    num_vertices_ = model.num_vertices;
    num_triangles_ = model.triangles ? model.num_triangles : 0;
    num_poses_ = model.poses ? model.num_poses : 0;
    if (num_vertices_ == 0) num_poses_ = 0;
    for (int i = 0; i < 3; ++i) {
        scale_[i] = model.scale[i];
        origin_[i] = model.origin[i];
    }
}

AliasTriangle AliasSource::triangle(uint32_t index) const {
    const int32_t* t = model_.triangles + static_cast<size_t>(index) * 4;
    return {t[0], {t[1], t[2], t[3]}};
}

PackedPosition AliasSource::packed(uint32_t pose, uint32_t vertex) const {
    // poses is a plain array (no size prefix): num_poses x num_vertices.
    const nqr_alias_vertex& v = model_.poses[static_cast<size_t>(pose) * num_vertices_ + vertex];
    return {v.v[0], v.v[1], v.v[2]};
}

glm::vec3 AliasSource::position(uint32_t pose, uint32_t vertex) const {
    const PackedPosition p = packed(pose, vertex);
    return scale_ * glm::vec3(p[0], p[1], p[2]) + origin_;
}

}  // namespace nq::npr::adjacency
