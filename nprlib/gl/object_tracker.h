// Counts the live OpenGL objects created through nprlib's owners, per kind. A renderer owns one
// tracker and hands it to every owner it creates, so after shutdown a test (or a debug check) can
// assert that nothing leaked. No global state: each tracker is a plain object.
#pragma once

#include <array>
#include <cstddef>

namespace nq::npr::gl {

enum class ObjectKind {
    buffer,
    vertex_array,
    texture,
    framebuffer,
    shader,
    program,
    sync,
    query,
    count
};

inline constexpr std::size_t kObjectKindCount = static_cast<std::size_t>(ObjectKind::count);

const char* object_kind_name(ObjectKind kind);

class ObjectTracker {
  public:
    void on_created(ObjectKind kind) {
        ++live_[index(kind)];
        ++created_[index(kind)];
    }
    void on_deleted(ObjectKind kind) { --live_[index(kind)]; }

    int live(ObjectKind kind) const { return live_[index(kind)]; }
    int created(ObjectKind kind) const { return created_[index(kind)]; }
    int total_live() const;

  private:
    static std::size_t index(ObjectKind kind) { return static_cast<std::size_t>(kind); }

    std::array<int, kObjectKindCount> live_{};
    std::array<int, kObjectKindCount> created_{};
};

}  // namespace nq::npr::gl
