#pragma once
// Triangles made on the CPU every frame (the overlay's glyphs and panels, line ribbons): a
// vertex array over one buffer of interleaved floats, refilled and drawn in one call. The
// attribute sizes are given once; attribute k is at location k.
#include <GL/gl.h>

#include <initializer_list>
#include <vector>

namespace tumble::render {

class VertexStream {
  public:
    // `sizes`: floats per attribute, e.g. {2, 2, 4} for position, uv, colour. Needs a current
    // GL context.
    explicit VertexStream(std::initializer_list<int> sizes);
    ~VertexStream();
    VertexStream(const VertexStream&) = delete;
    VertexStream& operator=(const VertexStream&) = delete;

    // Uploads `vertices` (whole vertices, back to back) and draws them as triangles with the
    // program, textures and state already set.
    void draw_triangles(const std::vector<float>& vertices) const;

  private:
    GLuint vao_ = 0, vbo_ = 0;
    int floats_per_vertex_ = 0;
};

} // namespace tumble::render
