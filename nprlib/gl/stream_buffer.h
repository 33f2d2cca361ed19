// A ring of GPU memory for per-frame dynamic data (particles, sprite quads, ...), written without
// any per-frame heap allocation. Two strategies:
//   persistent — GL 4.4 / ARB_buffer_storage: one persistently mapped buffer split into regions,
//                each fenced when the writer moves past it and waited on before it is reused;
//   orphaning  — GL 3.3: unsynchronised map of fresh ranges; when the ring is full the buffer's
//                storage is orphaned (glBufferData NULL) so the driver hands out new memory.
// Data pushed is valid for the draw calls issued before the next push that wraps past it.
#pragma once

#include <epoxy/gl.h>

#include <array>
#include <cstddef>
#include <cstdint>

#include "gl/handles.h"

namespace nq::npr::gl {

class StreamBuffer {
  public:
    enum class Mode { automatic, persistent, orphaning };

    static constexpr int kRegions = 4;
    // Offsets are aligned to a divisor of this (push/reserve refuse other alignments).
    static constexpr size_t kGranularity = 256;
    static constexpr size_t kNoSpace = static_cast<size_t>(-1);

    StreamBuffer() = default;
    ~StreamBuffer() { reset(); }
    StreamBuffer(const StreamBuffer&) = delete;
    StreamBuffer& operator=(const StreamBuffer&) = delete;

    // Creates the buffer (bound to GL_ARRAY_BUFFER while doing so). `automatic` picks persistent
    // when the context supports it. Returns false if persistent was demanded but is missing.
    bool create(ObjectTracker* tracker, size_t capacity_bytes, Mode mode = Mode::automatic);
    void reset();

    // Copies `bytes` into the ring at an offset aligned to `alignment` (a divisor of
    // kGranularity) and returns that offset, or kNoSpace when one push is larger than max_push()
    // or the alignment is not one.
    size_t push(const void* data, size_t bytes, size_t alignment = 16);

    // Reserves space and returns a writable pointer (valid until the next push/reserve) and its
    // offset; nullptr when the request is larger than max_push().
    void* reserve(size_t bytes, size_t alignment, size_t* offset_out);

    // Orphaning mode maps the range reserve() returns; this unmaps it. Call before drawing from
    // data written through reserve() (push() does it itself).
    void unmap();

    GLuint id() const { return buffer_.id(); }
    Mode mode() const { return mode_; }
    size_t capacity() const { return capacity_; }
    size_t max_push() const;
    int wraps() const { return wraps_; }

  private:
    void* reserve_persistent(size_t bytes, size_t alignment, size_t* offset_out);
    void* reserve_orphaning(size_t bytes, size_t alignment, size_t* offset_out);
    void fence_region(int region);
    void wait_region(int region);

    Buffer buffer_;
    ObjectTracker* tracker_ = nullptr;
    Mode mode_ = Mode::orphaning;
    size_t capacity_ = 0;
    size_t head_ = 0;
    uint8_t* persistent_ = nullptr;
    bool mapped_ = false;  // orphaning: a range is mapped until the next reserve or unmap
    std::array<GLsync, kRegions> fences_{};
    int region_ = 0;  // persistent: the region the last reservation lies in
    int wraps_ = 0;
};

bool context_supports_buffer_storage();

}  // namespace nq::npr::gl
