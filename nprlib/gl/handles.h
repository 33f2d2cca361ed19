// Move-only owners of OpenGL object names: Buffer, VertexArray, Texture, Framebuffer, Shader,
// ProgramName, Query. Each deletes its object on destruction (the GL context must still be current,
// as it is in a renderer's shutdown) and reports creation and deletion to an optional
// ObjectTracker.
#pragma once

#include <epoxy/gl.h>

#include <utility>

#include "gl/object_tracker.h"

namespace nq::npr::gl {

// glGen*/glCreate* for the kinds that need no argument; 0 for shader and sync.
GLuint generate_name(ObjectKind kind);
void delete_name(ObjectKind kind, GLuint id);

template <ObjectKind Kind>
class Handle {
  public:
    Handle() = default;
    ~Handle() { reset(); }

    Handle(Handle&& other) noexcept
        : id_(std::exchange(other.id_, 0)), tracker_(std::exchange(other.tracker_, nullptr)) {}
    Handle& operator=(Handle&& other) noexcept {
        if (this != &other) {
            reset();
            id_ = std::exchange(other.id_, 0);
            tracker_ = std::exchange(other.tracker_, nullptr);
        }
        return *this;
    }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;

    // A fresh object of this kind (not for shaders: use Shader::adopt(glCreateShader(stage))).
    static Handle create(ObjectTracker* tracker) { return adopt(generate_name(Kind), tracker); }

    // Takes ownership of a name made elsewhere (0 gives an empty handle).
    static Handle adopt(GLuint id, ObjectTracker* tracker) {
        Handle handle;
        handle.id_ = id;
        if (id != 0) {
            handle.tracker_ = tracker;
            if (tracker) tracker->on_created(Kind);
        }
        return handle;
    }

    GLuint id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }

    void reset() {
        if (id_ == 0) return;
        delete_name(Kind, id_);
        if (tracker_) tracker_->on_deleted(Kind);
        id_ = 0;
        tracker_ = nullptr;
    }

  private:
    GLuint id_ = 0;
    ObjectTracker* tracker_ = nullptr;
};

using Buffer = Handle<ObjectKind::buffer>;
using VertexArray = Handle<ObjectKind::vertex_array>;
using Texture = Handle<ObjectKind::texture>;
using Framebuffer = Handle<ObjectKind::framebuffer>;
using Shader = Handle<ObjectKind::shader>;
using ProgramName = Handle<ObjectKind::program>;
using Query = Handle<ObjectKind::query>;

}  // namespace nq::npr::gl
