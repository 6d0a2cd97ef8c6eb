#include "render/vertex_stream.h"

#include <GL/glext.h>

#include <cstdint>

namespace tumble::render {

VertexStream::VertexStream(std::initializer_list<int> sizes) {
    for (int n : sizes) floats_per_vertex_ += n;
    glGenVertexArrays(1, &vao_);
    glGenBuffers(1, &vbo_);
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    const auto stride = GLsizei(floats_per_vertex_ * sizeof(float));
    GLuint location = 0;
    std::uintptr_t offset = 0;
    for (int n : sizes) {
        glEnableVertexAttribArray(location);
        glVertexAttribPointer(location++, n, GL_FLOAT, GL_FALSE, stride,
                              reinterpret_cast<const void*>(offset));
        offset += std::uintptr_t(n) * sizeof(float);
    }
    glBindVertexArray(0);
}

VertexStream::~VertexStream() {
    if (vbo_) glDeleteBuffers(1, &vbo_);
    if (vao_) glDeleteVertexArrays(1, &vao_);
}

void VertexStream::draw_triangles(const std::vector<float>& vertices) const {
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(float)), vertices.data(),
                 GL_STREAM_DRAW);
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(vertices.size() / std::size_t(floats_per_vertex_)));
    glBindVertexArray(0);
}

} // namespace tumble::render
