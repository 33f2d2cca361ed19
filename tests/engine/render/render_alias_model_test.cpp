// Alias and sprite models as the renderer ABI sees them: every LibreQuake model's counts
// checked against its raw header, poses flattened in frame order, intervals, skins, bounds;
// every sprite's pictures and frames; the placeholder box.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "render/alias_model.h"
#include "render/placeholder_model.h"
#include "render/sprite_model.h"
#include "support/render_test_support.h"

namespace nq {
namespace {

using render_test::raw_i32;

std::vector<std::string> progs_with(const std::string& ext) {
    return render_test::lq1_vfs().list("progs", ext);
}

std::shared_ptr<const AliasModelData> load_alias(const std::string& path) {
    auto mdl = parse_mdl(render_test::lq1_bytes(path), path);
    if (!mdl) throw std::runtime_error(mdl.error().to_string());
    return AliasModelData::build(std::move(*mdl));
}

glm::vec3 decoded(const nqr_alias_model& a, const nqr_alias_vertex& v) {
    return {a.scale[0] * v.v[0] + a.origin[0], a.scale[1] * v.v[1] + a.origin[1],
            a.scale[2] * v.v[2] + a.origin[2]};
}

// Header fields at their documented offsets: num_skins 48, skin size 52/56, num_verts 60,
// num_tris 64, num_frames 68, flags 76.
TEST(RenderAliasModel, EveryModelKeepsTheHeaderCounts) {
    const auto paths = progs_with("mdl");
    ASSERT_GE(paths.size(), 80u);
    for (const std::string& path : paths) {
        const std::vector<uint8_t> raw = render_test::lq1_bytes(path);
        const auto data = load_alias(path);
        const nqr_alias_model& a = data->abi();
        EXPECT_EQ(a.size, sizeof(nqr_alias_model));
        EXPECT_EQ(a.num_skins, uint32_t(raw_i32(raw, 48))) << path;
        EXPECT_EQ(a.skin_width, raw_i32(raw, 52)) << path;
        EXPECT_EQ(a.skin_height, raw_i32(raw, 56)) << path;
        EXPECT_EQ(a.num_vertices, uint32_t(raw_i32(raw, 60))) << path;
        EXPECT_EQ(a.num_triangles, uint32_t(raw_i32(raw, 64))) << path;
        EXPECT_EQ(a.num_frames, uint32_t(raw_i32(raw, 68))) << path;
        EXPECT_EQ(a.flags, uint32_t(raw_i32(raw, 76))) << path;
    }
}

TEST(RenderAliasModel, PosesAreFlattenedInFrameOrderWithIntervals) {
    for (const std::string& path : progs_with("mdl")) {
        const auto data = load_alias(path);
        const nqr_alias_model& a = data->abi();
        const Mdl& mdl = data->mdl();
        uint32_t next_pose = 0;
        for (uint32_t f = 0; f < a.num_frames; ++f) {
            const nqr_alias_frame& frame = *nqr_at(nqr_alias_frame, a.frames, f);
            const MdlFrame& source = mdl.frames[f];
            EXPECT_EQ(frame.size, sizeof(nqr_alias_frame));
            ASSERT_EQ(frame.first_pose, next_pose) << path << " frame " << f;
            ASSERT_EQ(frame.num_poses, source.poses.size());
            EXPECT_STREQ(frame.name, source.poses[0].name.c_str());
            for (uint32_t p = 0; p < frame.num_poses; ++p) {
                const float expected = source.is_group ? source.intervals[p] : 0.1f * float(p + 1);
                EXPECT_FLOAT_EQ(frame.intervals[p], expected);
                for (uint32_t v = 0; v < a.num_vertices; ++v) {
                    const nqr_alias_vertex& out =
                        a.poses[size_t(frame.first_pose + p) * a.num_vertices + v];
                    const TriVertex& in = source.poses[p].vertices[v];
                    ASSERT_EQ(out.v[0], in.v[0]);
                    ASSERT_EQ(out.v[2], in.v[2]);
                    ASSERT_EQ(out.normal_index, in.light_normal_index);
                }
            }
            next_pose += frame.num_poses;
        }
        EXPECT_EQ(a.num_poses, next_pose) << path;
    }
}

TEST(RenderAliasModel, TexCoordsTrianglesAndSkinsAreCopied) {
    for (const std::string& path : progs_with("mdl")) {
        const auto data = load_alias(path);
        const nqr_alias_model& a = data->abi();
        const Mdl& mdl = data->mdl();
        for (uint32_t v = 0; v < a.num_vertices; ++v) {
            ASSERT_EQ(a.st[3 * v], mdl.tex_coords[v].on_seam);
            ASSERT_EQ(a.st[3 * v + 1], mdl.tex_coords[v].s);
            ASSERT_EQ(a.st[3 * v + 2], mdl.tex_coords[v].t);
        }
        for (uint32_t t = 0; t < a.num_triangles; ++t) {
            ASSERT_EQ(a.triangles[4 * t], mdl.triangles[t].faces_front);
            for (int k = 0; k < 3; ++k) {
                ASSERT_EQ(a.triangles[4 * t + 1 + k], mdl.triangles[t].vertices[k]);
                ASSERT_LT(uint32_t(a.triangles[4 * t + 1 + k]), a.num_vertices);
            }
        }
        for (uint32_t s = 0; s < a.num_skins; ++s) {
            const nqr_alias_skin& skin = *nqr_at(nqr_alias_skin, a.skins, s);
            EXPECT_EQ(skin.size, sizeof(nqr_alias_skin));
            ASSERT_EQ(skin.num_images, mdl.skins[s].images.size());
            for (uint32_t i = 0; i < skin.num_images; ++i) {
                EXPECT_EQ(skin.images[i], mdl.skins[s].images[i].data());
                EXPECT_GT(skin.intervals[i], 0.0f);
            }
        }
    }
}

TEST(RenderAliasModel, BoundsEncloseEveryPoseTightly) {
    for (const std::string& path : progs_with("mdl")) {
        const auto data = load_alias(path);
        const nqr_alias_model& a = data->abi();
        glm::vec3 lo(1e9f), hi(-1e9f);
        float radius = 0;
        for (size_t i = 0; i < size_t(a.num_poses) * a.num_vertices; ++i) {
            const glm::vec3 p = decoded(a, a.poses[i]);
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
            radius = std::max(radius, glm::length(p));
        }
        for (int c = 0; c < 3; ++c) {
            EXPECT_FLOAT_EQ(data->mins()[c], lo[c]) << path;
            EXPECT_FLOAT_EQ(data->maxs()[c], hi[c]) << path;
        }
        EXPECT_FLOAT_EQ(data->radius(), radius) << path;
    }
}

// Each pose's box from its own vertices through the ABI's poses; a pose past the last gets the
// whole model's box (a malformed entity frame must never cull a model that is on screen).
TEST(RenderAliasModel, EachPoseHasItsOwnTightBounds) {
    size_t smaller_than_model = 0, poses_seen = 0;
    for (const std::string& path : progs_with("mdl")) {
        const auto data = load_alias(path);
        const nqr_alias_model& a = data->abi();
        for (uint32_t pose = 0; pose < a.num_poses; ++pose) {
            glm::vec3 lo(1e9f), hi(-1e9f);
            for (uint32_t v = 0; v < a.num_vertices; ++v) {
                const glm::vec3 p = decoded(a, a.poses[size_t(pose) * a.num_vertices + v]);
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
            }
            const AliasModelData::PoseBounds b = data->pose_bounds(pose);
            for (int c = 0; c < 3; ++c) {
                ASSERT_FLOAT_EQ(b.mins[c], lo[c]) << path << " pose " << pose;
                ASSERT_FLOAT_EQ(b.maxs[c], hi[c]) << path << " pose " << pose;
            }
            ++poses_seen;
            if (glm::any(glm::greaterThan(b.mins, data->mins())) ||
                glm::any(glm::lessThan(b.maxs, data->maxs()))) {
                ++smaller_than_model;
            }
        }
        const AliasModelData::PoseBounds past = data->pose_bounds(a.num_poses);
        EXPECT_EQ(past.mins, data->mins()) << path;
        EXPECT_EQ(past.maxs, data->maxs()) << path;
    }
    // Animated models move their limbs: most poses fill less than the model's box.
    EXPECT_GT(smaller_than_model, poses_seen / 2);
}

TEST(RenderSpriteModel, EverySpriteKeepsPicturesAndFrames) {
    const auto paths = progs_with("spr");
    ASSERT_GE(paths.size(), 4u);
    for (const std::string& path : paths) {
        const std::vector<uint8_t> raw = render_test::lq1_bytes(path);
        auto spr = parse_spr(raw, path);
        ASSERT_TRUE(spr) << spr.error().to_string();
        const Spr copy = *spr;
        const auto data = SpriteModelData::build(std::move(*spr));
        const nqr_sprite_model& s = data->abi();
        EXPECT_EQ(s.size, sizeof(nqr_sprite_model));
        EXPECT_EQ(s.type, uint32_t(raw_i32(raw, 8))) << path;         // header: type at 8
        EXPECT_EQ(s.num_frames, uint32_t(raw_i32(raw, 24))) << path;  // num_frames at 24
        uint32_t next = 0;
        for (uint32_t f = 0; f < s.num_frames; ++f) {
            const nqr_sprite_frame& frame = *nqr_at(nqr_sprite_frame, s.frames, f);
            ASSERT_EQ(frame.first_image, next);
            ASSERT_EQ(frame.num_images, copy.frames[f].pictures.size());
            for (uint32_t i = 0; i < frame.num_images; ++i) {
                const nqr_sprite_image& image = *nqr_at(nqr_sprite_image, s.images, next + i);
                const SprPicture& picture = copy.frames[f].pictures[i];
                EXPECT_EQ(image.width, picture.width);
                EXPECT_EQ(image.height, picture.height);
                EXPECT_EQ(image.origin_x, picture.origin_x);
                EXPECT_EQ(image.origin_y, picture.origin_y);
                EXPECT_EQ(0,
                          std::memcmp(image.pixels, picture.pixels.data(), picture.pixels.size()));
                EXPECT_GT(frame.intervals[i], 0.0f);
                // The picture lies within the sprite's radius.
                EXPECT_LE(std::hypot(float(image.origin_x), float(image.origin_y)), data->radius());
            }
            next += frame.num_images;
        }
        EXPECT_EQ(s.num_images, next);
    }
}

TEST(RenderPlaceholderModel, IsASixteenUnitBoxOfOneColour) {
    const auto data = make_placeholder_alias();
    const nqr_alias_model& a = data->abi();
    EXPECT_EQ(a.num_vertices, 8u);
    EXPECT_EQ(a.num_triangles, 12u);
    EXPECT_EQ(a.num_frames, 1u);
    EXPECT_EQ(a.num_poses, 1u);
    ASSERT_EQ(a.num_skins, 1u);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(data->mins()[c], -8.0f, 1e-4f);
        EXPECT_NEAR(data->maxs()[c], 8.0f, 1e-4f);
    }
    const uint8_t* skin = a.skins->images[0];
    for (int i = 0; i < a.skin_width * a.skin_height; ++i) ASSERT_EQ(skin[i], kPlaceholderColor);
}

// Sign of (b - a) x (c - a) against the direction from the model's centre: the winding rule.
int winding_vote(const nqr_alias_model& a, glm::vec3 center) {
    int vote = 0;
    for (uint32_t t = 0; t < a.num_triangles; ++t) {
        glm::vec3 p[3];
        for (int k = 0; k < 3; ++k) p[k] = decoded(a, a.poses[a.triangles[4 * t + 1 + k]]);
        const glm::vec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
        const float d = glm::dot(n, (p[0] + p[1] + p[2]) / 3.0f - center);
        vote += d > 0 ? 1 : d < 0 ? -1 : 0;
    }
    return vote;
}

// The placeholder winds its triangles the way real models do (judged by the majority of
// triangles of a few closed, roughly convex models).
TEST(RenderPlaceholderModel, WindsTrianglesLikeRealModels) {
    int real = 0;
    for (const char* path : {"progs/armor.mdl", "progs/backpack.mdl", "progs/grenade.mdl"}) {
        const auto data = load_alias(path);
        real += winding_vote(data->abi(), (data->mins() + data->maxs()) * 0.5f);
    }
    ASSERT_NE(real, 0);
    const auto box = make_placeholder_alias();
    const int placeholder = winding_vote(box->abi(), glm::vec3(0.0f));
    EXPECT_EQ(std::abs(placeholder), 12);
    EXPECT_EQ(placeholder > 0, real > 0);
}

}  // namespace
}  // namespace nq
