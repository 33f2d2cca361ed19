#include "gl/stream_buffer.h"

#include <cstring>

namespace nq::npr::gl {
namespace {

size_t align_up(size_t value, size_t alignment) {
    if (alignment <= 1) return value;
    return (value + alignment - 1) / alignment * alignment;
}

constexpr GLbitfield kPersistentFlags =
    GL_MAP_WRITE_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;

}  // namespace

bool context_supports_buffer_storage() {
    return epoxy_gl_version() >= 44 || epoxy_has_gl_extension("GL_ARB_buffer_storage");
}

bool StreamBuffer::create(ObjectTracker* tracker, size_t capacity_bytes, Mode mode) {
    reset();
    const bool storage = context_supports_buffer_storage();
    if (mode == Mode::persistent && !storage) return false;
    mode_ = (mode == Mode::automatic) ? (storage ? Mode::persistent : Mode::orphaning) : mode;
    tracker_ = tracker;
    capacity_ = align_up(capacity_bytes, kGranularity * kRegions);
    buffer_ = Buffer::create(tracker);
    glBindBuffer(GL_ARRAY_BUFFER, buffer_.id());
    if (mode_ == Mode::persistent) {
        glBufferStorage(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(capacity_), nullptr,
                        kPersistentFlags);
        persistent_ = static_cast<uint8_t*>(glMapBufferRange(
            GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(capacity_), kPersistentFlags));
    } else {
        glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(capacity_), nullptr, GL_STREAM_DRAW);
    }
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    head_ = 0;
    region_ = 0;
    wraps_ = 0;
    return mode_ != Mode::persistent || persistent_ != nullptr;
}

void StreamBuffer::reset() {
    if (!buffer_) return;
    for (GLsync& fence : fences_) {
        if (fence) {
            glDeleteSync(fence);
            if (tracker_) tracker_->on_deleted(ObjectKind::sync);
            fence = nullptr;
        }
    }
    if (persistent_ || mapped_) {
        glBindBuffer(GL_ARRAY_BUFFER, buffer_.id());
        glUnmapBuffer(GL_ARRAY_BUFFER);
        glBindBuffer(GL_ARRAY_BUFFER, 0);
    }
    persistent_ = nullptr;
    mapped_ = false;
    buffer_.reset();
    capacity_ = 0;
    head_ = 0;
}

size_t StreamBuffer::max_push() const {
    return mode_ == Mode::persistent ? capacity_ / kRegions : capacity_;
}

size_t StreamBuffer::push(const void* data, size_t bytes, size_t alignment) {
    size_t offset = 0;
    void* target = reserve(bytes, alignment, &offset);
    if (!target) return kNoSpace;
    std::memcpy(target, data, bytes);
    unmap();
    return offset;
}

void* StreamBuffer::reserve(size_t bytes, size_t alignment, size_t* offset_out) {
    // Regions start at multiples of kGranularity: an alignment that divides it holds there too.
    if (alignment > kGranularity || (alignment != 0 && kGranularity % alignment != 0)) {
        return nullptr;
    }
    if (!buffer_ || bytes == 0 || bytes > max_push()) return nullptr;
    unmap();
    return mode_ == Mode::persistent ? reserve_persistent(bytes, alignment, offset_out)
                                     : reserve_orphaning(bytes, alignment, offset_out);
}

void StreamBuffer::unmap() {
    if (!mapped_) return;
    glBindBuffer(GL_ARRAY_BUFFER, buffer_.id());
    glUnmapBuffer(GL_ARRAY_BUFFER);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    mapped_ = false;
}

void StreamBuffer::fence_region(int region) {
    if (fences_[region]) {
        glDeleteSync(fences_[region]);
        if (tracker_) tracker_->on_deleted(ObjectKind::sync);
    }
    fences_[region] = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    if (tracker_ && fences_[region]) tracker_->on_created(ObjectKind::sync);
}

void StreamBuffer::wait_region(int region) {
    GLsync fence = fences_[region];
    if (!fence) return;
    // Waits only if the GPU still reads this region from the previous lap of the ring.
    while (glClientWaitSync(fence, GL_SYNC_FLUSH_COMMANDS_BIT, 1'000'000) == GL_TIMEOUT_EXPIRED) {
    }
    glDeleteSync(fence);
    if (tracker_) tracker_->on_deleted(ObjectKind::sync);
    fences_[region] = nullptr;
}

void* StreamBuffer::reserve_persistent(size_t bytes, size_t alignment, size_t* offset_out) {
    const size_t region_size = capacity_ / kRegions;
    size_t offset = align_up(head_, alignment);
    if (offset + bytes > static_cast<size_t>(region_ + 1) * region_size) {
        // Leaving the region: every draw that reads it has been issued, so fence it; then wait
        // until the GPU is done with the next region's data from the previous lap.
        fence_region(region_);
        region_ = (region_ + 1) % kRegions;
        if (region_ == 0) ++wraps_;
        wait_region(region_);
        offset = static_cast<size_t>(region_) * region_size;
    }
    head_ = offset + bytes;
    *offset_out = offset;
    return persistent_ + offset;
}

void* StreamBuffer::reserve_orphaning(size_t bytes, size_t alignment, size_t* offset_out) {
    size_t offset = align_up(head_, alignment);
    glBindBuffer(GL_ARRAY_BUFFER, buffer_.id());
    GLbitfield access = GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_RANGE_BIT | GL_MAP_UNSYNCHRONIZED_BIT;
    if (offset + bytes > capacity_) {
        // Full: orphan the storage; draws already issued keep reading the old copy.
        glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(capacity_), nullptr, GL_STREAM_DRAW);
        offset = 0;
        ++wraps_;
        access = GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_BUFFER_BIT;
    }
    void* target = glMapBufferRange(GL_ARRAY_BUFFER, static_cast<GLintptr>(offset),
                                    static_cast<GLsizeiptr>(bytes), access);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    if (!target) return nullptr;
    mapped_ = true;
    head_ = offset + bytes;
    *offset_out = offset;
    return target;
}

}  // namespace nq::npr::gl
