#include "console/console_drawer.h"

#include <cstddef>
#include <cstdint>
#include <vector>

#include "console/console_shader.h"
#include "console/overlay_gl_state.h"
#include "console/rgba_texture.h"

namespace nq {
namespace {

constexpr Colour kBackgroundImageTint{255, 255, 255, 255};

void* byte_offset(size_t offset) {
    return reinterpret_cast<void*>(offset);
}

// Keeps the caller's vertex array and program bound after the drawer is done.
class BindingRestore {
  public:
    BindingRestore() {
        glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertex_array_);
        glGetIntegerv(GL_CURRENT_PROGRAM, &program_);
        glGetIntegerv(GL_ACTIVE_TEXTURE, &active_texture_);
        glActiveTexture(GL_TEXTURE0);
        glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture_);
        glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &array_buffer_);
    }
    ~BindingRestore() {
        glBindVertexArray(static_cast<GLuint>(vertex_array_));
        glUseProgram(static_cast<GLuint>(program_));
        glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(texture_));
        glActiveTexture(static_cast<GLenum>(active_texture_));
        glBindBuffer(GL_ARRAY_BUFFER, static_cast<GLuint>(array_buffer_));
    }
    BindingRestore(const BindingRestore&) = delete;
    BindingRestore& operator=(const BindingRestore&) = delete;

  private:
    GLint vertex_array_ = 0, program_ = 0, active_texture_ = 0, texture_ = 0, array_buffer_ = 0;
};

}  // namespace

Result<ConsoleDrawer> ConsoleDrawer::create(ConsoleStyle style) {
    Result<GlProgram> program = build_console_program();
    if (!program) return program.error();
    ConsoleDrawer drawer(std::move(*program), style);
    drawer.create_buffers();
    drawer.use_fallback_font();
    return drawer;
}

ConsoleDrawer::ConsoleDrawer(GlProgram program, ConsoleStyle style)
    : program_(std::move(program)), scene_(style) {
    screen_size_location_ = glGetUniformLocation(program_.id(), "screen_size");
    batch_.set_flush([this](std::span<const QuadVertex> vertices) { flush(vertices); });
}

ConsoleDrawer::ConsoleDrawer(ConsoleDrawer&& other) noexcept
    : program_(std::move(other.program_)),
      vertex_array_(std::move(other.vertex_array_)),
      vertex_buffer_(std::move(other.vertex_buffer_)),
      index_buffer_(std::move(other.index_buffer_)),
      font_(std::move(other.font_)),
      background_(std::move(other.background_)),
      screen_size_location_(other.screen_size_location_),
      scene_(std::move(other.scene_)),
      batch_(std::move(other.batch_)),
      draw_calls_(other.draw_calls_),
      quads_drawn_(other.quads_drawn_) {
    batch_.set_flush([this](std::span<const QuadVertex> vertices) { flush(vertices); });
}

void ConsoleDrawer::create_buffers() {
    vertex_array_ = GlVertexArray::generate();
    vertex_buffer_ = GlBuffer::generate();
    index_buffer_ = GlBuffer::generate();

    GLint previous_array = 0, previous_buffer = 0;
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &previous_array);
    glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &previous_buffer);
    glBindVertexArray(vertex_array_.id());
    glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer_.id());
    glBufferData(GL_ARRAY_BUFFER,
                 static_cast<GLsizeiptr>(batch_.capacity() * kVerticesPerQuad * sizeof(QuadVertex)),
                 nullptr, GL_STREAM_DRAW);
    constexpr GLsizei kStride = sizeof(QuadVertex);
    glEnableVertexAttribArray(kConsolePositionAttribute);
    glVertexAttribPointer(kConsolePositionAttribute, 2, GL_FLOAT, GL_FALSE, kStride,
                          byte_offset(offsetof(QuadVertex, x)));
    glEnableVertexAttribArray(kConsoleUvAttribute);
    glVertexAttribPointer(kConsoleUvAttribute, 2, GL_FLOAT, GL_FALSE, kStride,
                          byte_offset(offsetof(QuadVertex, u)));
    glEnableVertexAttribArray(kConsoleColourAttribute);
    glVertexAttribPointer(kConsoleColourAttribute, 4, GL_UNSIGNED_BYTE, GL_TRUE, kStride,
                          byte_offset(offsetof(QuadVertex, r)));
    glEnableVertexAttribArray(kConsoleTexturedAttribute);
    glVertexAttribPointer(kConsoleTexturedAttribute, 1, GL_UNSIGNED_BYTE, GL_TRUE, kStride,
                          byte_offset(offsetof(QuadVertex, textured)));
    upload_indices();  // the element buffer binding is part of the vertex array
    glBindVertexArray(static_cast<GLuint>(previous_array));
    glBindBuffer(GL_ARRAY_BUFFER, static_cast<GLuint>(previous_buffer));
}

void ConsoleDrawer::upload_indices() {
    // Two triangles per quad over its 4 vertices; 16-bit indices cover kQuadBatchCapacity.
    static_assert(kQuadBatchCapacity * kVerticesPerQuad <= 65536);
    std::vector<uint16_t> indices(batch_.capacity() * kIndicesPerQuad);
    for (size_t quad = 0; quad < batch_.capacity(); ++quad) {
        auto first = static_cast<uint16_t>(quad * kVerticesPerQuad);
        uint16_t* out = &indices[quad * kIndicesPerQuad];
        out[0] = first;
        out[1] = static_cast<uint16_t>(first + 1);
        out[2] = static_cast<uint16_t>(first + 2);
        out[3] = first;
        out[4] = static_cast<uint16_t>(first + 2);
        out[5] = static_cast<uint16_t>(first + 3);
    }
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, index_buffer_.id());
    glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                 static_cast<GLsizeiptr>(indices.size() * sizeof(uint16_t)), indices.data(),
                 GL_STATIC_DRAW);
}

void ConsoleDrawer::set_font(const RgbaImage& font) {
    if (font.width != kFontImageSize || font.height != kFontImageSize) return;
    if (!font_) font_ = GlTexture::generate();
    upload_rgba_texture(font_.id(), font.width, font.height, font.rgba.data());
}

void ConsoleDrawer::set_background(const RgbaImage& image) {
    if (image.width <= 0 || image.height <= 0 || image.rgba.empty()) {
        background_.reset();
        return;
    }
    if (!background_) background_ = GlTexture::generate();
    upload_rgba_texture(background_.id(), image.width, image.height, image.rgba.data());
}

void ConsoleDrawer::flush(std::span<const QuadVertex> vertices) {
    size_t quads = vertices.size() / kVerticesPerQuad;
    if (quads == 0) return;
    // Orphan the buffer's storage so the driver need not wait for the previous draw.
    GLsizeiptr capacity_bytes =
        static_cast<GLsizeiptr>(batch_.capacity() * kVerticesPerQuad * sizeof(QuadVertex));
    glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer_.id());
    glBufferData(GL_ARRAY_BUFFER, capacity_bytes, nullptr, GL_STREAM_DRAW);
    glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(vertices.size_bytes()),
                    vertices.data());
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(quads * kIndicesPerQuad), GL_UNSIGNED_SHORT,
                   nullptr);
    ++draw_calls_;
    quads_drawn_ += quads;
}

void ConsoleDrawer::draw_background_image(const Console& console) {
    auto [x, y, width, height] = scene_.background_rect(console);
    glBindTexture(GL_TEXTURE_2D, background_.id());
    batch_.image(x, y, width, height, kBackgroundImageTint);
    batch_.flush();
}

void ConsoleDrawer::draw(const Console& console) {
    draw_calls_ = 0;
    quads_drawn_ = 0;
    const ConsoleLayout& layout = console.layout();
    if (layout.screen_width <= 0 || layout.screen_height <= 0) return;
    if (!scene_.has_content(console)) return;

    OverlayGlState state(layout.screen_width, layout.screen_height);
    BindingRestore bindings;
    glUseProgram(program_.id());
    glUniform2f(screen_size_location_, static_cast<float>(layout.screen_width),
                static_cast<float>(layout.screen_height));
    glBindVertexArray(vertex_array_.id());

    batch_.clear();
    bool image_background = background_ && console.height_pixels() > 0;
    if (image_background) draw_background_image(console);
    glBindTexture(GL_TEXTURE_2D, font_.id());
    scene_.build(console, batch_, !image_background);
    batch_.flush();
}

}  // namespace nq
