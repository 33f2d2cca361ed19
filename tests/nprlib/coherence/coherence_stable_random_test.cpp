// Stateless randomness (coherence/stable_random.h): the properties the styles rely on, checked
// against facts computed here — a bijective mixer, full avalanche, even spread, epochs locked to
// demo time at any frame rate, distinct kinds and particles — and the GLSL twin giving the very
// same bits on the GPU.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <unordered_set>
#include <vector>

#include "coherence/stable_random.h"
#include "gl/object_tracker.h"
#include "gl/program.h"
#include "support/nprlib_test_support.h"

namespace nq::npr::test {
namespace {

using coherence::boil_epoch;
using coherence::hash_words;
using coherence::mix32;
using coherence::primitive_id;
using coherence::PrimitiveKind;
using coherence::StableRandom;

TEST(StableRandom, TheMixerIsABijection) {
    // A bijection on 32 bits maps 2^20 distinct inputs to 2^20 distinct outputs.
    std::vector<uint32_t> out;
    out.reserve(1u << 20);
    for (uint32_t i = 0; i < (1u << 20); ++i) out.push_back(mix32(i * 4099u + 7u));
    std::sort(out.begin(), out.end());
    EXPECT_EQ(std::adjacent_find(out.begin(), out.end()), out.end());
    EXPECT_EQ(mix32(0), 0u) << "xor-shift-multiply keeps 0: why hash_words offsets each word";
    EXPECT_NE(hash_words({0}), 0u);
}

TEST(StableRandom, EveryInputBitReachesEveryOutputBit) {
    // Flipping one bit of one word flips each output bit with probability about 1/2.
    std::array<int, 32> flips{};
    int trials = 0;
    double total = 0;
    for (uint32_t n = 0; n < 500; ++n) {
        const std::array<uint32_t, 4> w = {mix32(n + 1), mix32(n + 1001), n, n * 7u};
        const uint32_t base = hash_words({w[0], w[1], w[2], w[3]});
        for (int word = 0; word < 4; ++word) {
            for (int bit = 0; bit < 32; ++bit) {
                std::array<uint32_t, 4> v = w;
                v[word] ^= 1u << bit;
                const uint32_t diff = base ^ hash_words({v[0], v[1], v[2], v[3]});
                total += std::popcount(diff);
                for (int k = 0; k < 32; ++k) flips[k] += (diff >> k) & 1u;
                ++trials;
            }
        }
    }
    EXPECT_NEAR(total / trials, 16.0, 0.25);
    for (int k = 0; k < 32; ++k) EXPECT_NEAR(double(flips[k]) / trials, 0.5, 0.03) << "bit " << k;
}

TEST(StableRandom, UnitValuesSpreadEvenlyOverZeroToOne) {
    // 100,000 primitives' first value in 100 bins: chi-square below its 0.1% point for 99
    // degrees of freedom (148.2); every value in [0, 1).
    constexpr int kBins = 100, kCount = 100000;
    std::array<int, kBins> bins{};
    for (uint32_t id = 0; id < kCount; ++id) {
        const float u =
            StableRandom(1234, primitive_id(PrimitiveKind::model_edge, 7, id), 0).unit(0);
        ASSERT_GE(u, 0.0f);
        ASSERT_LT(u, 1.0f);
        ++bins[static_cast<int>(u * kBins)];
    }
    const double expected = double(kCount) / kBins;
    double chi2 = 0;
    for (int b : bins) chi2 += (b - expected) * (b - expected) / expected;
    EXPECT_LT(chi2, 148.2);
    const StableRandom r(1, 2, 3);
    EXPECT_GE(r.range(5, -2.0f, 6.0f), -2.0f);
    EXPECT_LT(r.range(5, -2.0f, 6.0f), 6.0f);
}

TEST(StableRandom, FrozenStylesNeverChangeTheirEpoch) {
    for (double t : {0.0, 0.01, 1.0 / 3.0, 7.5, 1234.5}) {
        EXPECT_EQ(boil_epoch(t, 0.0), 0u) << t;
        EXPECT_EQ(boil_epoch(t, -12.0), 0u) << t;
    }
    EXPECT_EQ(boil_epoch(-3.0, 12.0), 0u) << "before the demo's first frame";
    EXPECT_EQ(boil_epoch(2.5, 8.0), 20u);
    EXPECT_EQ(boil_epoch(1e12, 12.0), 0xffffffffu) << "saturates, never wraps";
}

// A style boiling at 12 Hz renders frames at 30, 60 and 144 fps: its strokes change at the first
// frame at or after each 1/12 s of demo time, the same stroke shows at the same demo time at
// every rate, and an epoch change redraws (almost) every stroke.
TEST(StableRandom, BoilingIsLockedToDemoTimeAtAnyFrameRate) {
    constexpr double kHz = 12.0, kSeconds = 2.0;
    for (const int fps : {30, 60, 144}) {
        SCOPED_TRACE(std::to_string(fps) + " fps");
        std::vector<double> changes;
        uint32_t last = boil_epoch(0.0, kHz);
        for (int frame = 1; frame <= int(kSeconds * fps); ++frame) {
            const double t = double(frame) / fps;
            const uint32_t epoch = boil_epoch(t, kHz);
            if (epoch != last) changes.push_back(t);
            EXPECT_LE(epoch, last + 1) << "at most one epoch a frame at these rates";
            last = epoch;
            // Every 1/6 s is a frame at all three rates (t = n/30 = m/144): there the epoch,
            // and so every stroke, is the one a 30 fps renderer computed for its frame n.
            if ((frame * 6) % fps == 0) {
                const int n = frame * 30 / fps;
                EXPECT_EQ(epoch, boil_epoch(double(n) / 30, kHz)) << "t = " << t;
                EXPECT_EQ(StableRandom(9, 42, epoch).bits(0),
                          StableRandom(9, 42, boil_epoch(double(n) / 30, kHz)).bits(0));
            }
        }
        ASSERT_EQ(changes.size(), size_t(kHz * kSeconds));
        for (size_t k = 0; k < changes.size(); ++k) {
            const double boundary = double(k + 1) / kHz;
            EXPECT_GE(changes[k], boundary - 1e-6);
            EXPECT_LT(changes[k], boundary + 1.0 / fps) << "the first frame after the boundary";
        }
    }
    int same = 0;
    for (uint32_t id = 0; id < 10000; ++id)
        same += StableRandom(9, id, 4).bits(0) == StableRandom(9, id, 5).bits(0);
    EXPECT_LE(same, 1);
}

TEST(StableRandom, KindsOwnersAndParticlesKeepTheirIdsApart) {
    std::unordered_set<uint32_t> ids;
    for (uint32_t i = 0; i < 2000; ++i) {
        for (auto kind : {PrimitiveKind::world_face, PrimitiveKind::world_edge,
                          PrimitiveKind::model_triangle, PrimitiveKind::model_edge}) {
            ids.insert(primitive_id(kind, 0, i));
            ids.insert(primitive_id(kind, 3, i));
        }
    }
    EXPECT_EQ(ids.size(), 2000u * 4 * 2);
    EXPECT_EQ(coherence::particle_id(5, 1.25), coherence::particle_id(5, 1.2501))
        << "one particle: its spawn time to the millisecond";
    EXPECT_NE(coherence::particle_id(5, 1.25), coherence::particle_id(5, 1.5)) << "slot reused";
    EXPECT_NE(coherence::particle_id(5, 1.25), coherence::particle_id(6, 1.25));
}

// The shaders' hash: a fragment shader writes nq_hash4(seed, pixel index, epoch, stream) into an
// unsigned-integer texture; every pixel equals StableRandom::bits on the CPU.
class StableRandomGpu : public GlSuiteTest<StableRandomGpu> {};

TEST_F(StableRandomGpu, TheGlslTwinGivesTheSameBits) {
    constexpr int kSide = 64;
    constexpr uint32_t kSeed = 77, kEpoch = 5, kStream = 3;
    const std::string fragment =
        std::string("#version 330 core\n") + coherence::kStableRandomGlsl + R"(
uniform uint u_seed, u_epoch, u_stream;
layout(location = 0) out uint o_bits;
void main() {
    uint index = uint(gl_FragCoord.y) * 64u + uint(gl_FragCoord.x);
    o_bits = nq_hash4(u_seed, index, u_epoch, u_stream);
}
)";
    constexpr char kVertex[] = R"(#version 330 core
void main() {
    vec2 p = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);
    gl_Position = vec4(p, 0.0, 1.0);
}
)";
    gl::ObjectTracker tracker;
    gl::ProgramBuild build =
        gl::Program::build({"stable random", kVertex, fragment.c_str()}, &tracker);
    ASSERT_TRUE(build.ok()) << build.error;
    GLuint texture = 0, framebuffer = 0, vao = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R32UI, kSide, kSide, 0, GL_RED_INTEGER, GL_UNSIGNED_INT,
                 nullptr);
    glGenFramebuffers(1, &framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
    ASSERT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glViewport(0, 0, kSide, kSide);
    glDisable(GL_DEPTH_TEST);
    build.program.use();
    glUniform1ui(build.program.location("u_seed"), kSeed);
    glUniform1ui(build.program.location("u_epoch"), kEpoch);
    glUniform1ui(build.program.location("u_stream"), kStream);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    std::vector<uint32_t> gpu(kSide * kSide);
    glReadPixels(0, 0, kSide, kSide, GL_RED_INTEGER, GL_UNSIGNED_INT, gpu.data());
    ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    glUseProgram(0);
    glBindVertexArray(0);
    glDeleteVertexArrays(1, &vao);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteTextures(1, &texture);
    gl_->bind();
    int mismatches = 0;
    for (uint32_t i = 0; i < gpu.size(); ++i) {
        mismatches += gpu[i] != StableRandom(kSeed, i, kEpoch).bits(kStream);
    }
    EXPECT_EQ(mismatches, 0);
    EXPECT_EQ(gpu[1234], StableRandom(kSeed, 1234, kEpoch).bits(kStream));
}

}  // namespace
}  // namespace nq::npr::test
