#include "draw2d/quad_renderer.h"

#include <cstdint>
#include <vector>

#include "draw2d/quad_shader.h"

namespace nq {
namespace {

void* byte_offset(size_t offset) {
    return reinterpret_cast<void*>(offset);
}

}  // namespace

Result<QuadRenderer> QuadRenderer::create(size_t capacity_quads) {
    Result<npr::gl::Program> program = build_quad_program();
    if (!program) return program.error();
    QuadRenderer renderer(std::move(*program), capacity_quads);
    renderer.create_buffers();
    return renderer;
}

QuadRenderer::QuadRenderer(npr::gl::Program program, size_t capacity_quads)
    : program_(std::move(program)), batch_(capacity_quads) {
    screen_size_location_ = glGetUniformLocation(program_.id(), "screen_size");
    batch_.set_flush([this](std::span<const QuadVertex> vertices) { flush(vertices); });
}

QuadRenderer::QuadRenderer(QuadRenderer&& other) noexcept
    : program_(std::move(other.program_)),
      vertex_array_(std::move(other.vertex_array_)),
      vertex_buffer_(std::move(other.vertex_buffer_)),
      index_buffer_(std::move(other.index_buffer_)),
      screen_size_location_(other.screen_size_location_),
      batch_(std::move(other.batch_)),
      draw_calls_(other.draw_calls_),
      quads_drawn_(other.quads_drawn_) {
    // The flush callback must call this object, not the one moved from.
    batch_.set_flush([this](std::span<const QuadVertex> vertices) { flush(vertices); });
}

void QuadRenderer::create_buffers() {
    vertex_array_ = npr::gl::VertexArray::create(nullptr);
    vertex_buffer_ = npr::gl::Buffer::create(nullptr);
    index_buffer_ = npr::gl::Buffer::create(nullptr);

    GLint previous_array = 0, previous_buffer = 0;
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &previous_array);
    glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &previous_buffer);
    glBindVertexArray(vertex_array_.id());
    glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer_.id());
    glBufferData(GL_ARRAY_BUFFER,
                 static_cast<GLsizeiptr>(batch_.capacity() * kVerticesPerQuad * sizeof(QuadVertex)),
                 nullptr, GL_STREAM_DRAW);
    constexpr GLsizei kStride = sizeof(QuadVertex);
    glEnableVertexAttribArray(kQuadPositionAttribute);
    glVertexAttribPointer(kQuadPositionAttribute, 2, GL_FLOAT, GL_FALSE, kStride,
                          byte_offset(offsetof(QuadVertex, x)));
    glEnableVertexAttribArray(kQuadUvAttribute);
    glVertexAttribPointer(kQuadUvAttribute, 2, GL_FLOAT, GL_FALSE, kStride,
                          byte_offset(offsetof(QuadVertex, u)));
    glEnableVertexAttribArray(kQuadColourAttribute);
    glVertexAttribPointer(kQuadColourAttribute, 4, GL_UNSIGNED_BYTE, GL_TRUE, kStride,
                          byte_offset(offsetof(QuadVertex, r)));
    glEnableVertexAttribArray(kQuadSamplingAttribute);
    glVertexAttribPointer(kQuadSamplingAttribute, 1, GL_UNSIGNED_BYTE, GL_TRUE, kStride,
                          byte_offset(offsetof(QuadVertex, sampling)));
    upload_indices();  // the element buffer binding is part of the vertex array
    glBindVertexArray(static_cast<GLuint>(previous_array));
    glBindBuffer(GL_ARRAY_BUFFER, static_cast<GLuint>(previous_buffer));
}

void QuadRenderer::upload_indices() {
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

void QuadRenderer::flush(std::span<const QuadVertex> vertices) {
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

QuadRenderer::Pass::BindingRestore::BindingRestore() {
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertex_array_);
    glGetIntegerv(GL_CURRENT_PROGRAM, &program_);
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active_texture_);
    glActiveTexture(GL_TEXTURE0);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture_);
    glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &array_buffer_);
}

QuadRenderer::Pass::BindingRestore::~BindingRestore() {
    glBindVertexArray(static_cast<GLuint>(vertex_array_));
    glUseProgram(static_cast<GLuint>(program_));
    glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(texture_));
    glActiveTexture(static_cast<GLenum>(active_texture_));
    glBindBuffer(GL_ARRAY_BUFFER, static_cast<GLuint>(array_buffer_));
}

QuadRenderer::Pass::Pass(QuadRenderer& renderer, int width, int height)
    : renderer_(renderer), state_(width, height) {
    renderer_.draw_calls_ = 0;
    renderer_.quads_drawn_ = 0;
    renderer_.batch_.clear();
    glUseProgram(renderer_.program_.id());
    glUniform2f(renderer_.screen_size_location_, static_cast<float>(width),
                static_cast<float>(height));
    glBindVertexArray(renderer_.vertex_array_.id());
}

QuadRenderer::Pass::~Pass() {
    renderer_.batch_.flush();
}

void QuadRenderer::Pass::use_texture(GLuint texture) {
    renderer_.batch_.flush();
    glBindTexture(GL_TEXTURE_2D, texture);
}

}  // namespace nq
