#pragma once
// GLSL programs: compile two stages, link them, and report failures with the shader's name and
// the driver's log, so a typo in lit.frag says "lit.frag:12: ..." rather than "draw failed".
//
// Every stage is compiled from four strings (glShaderSource takes a list):
//   1. "#version 330 core"       the GLSL dialect of GL 3.3 core
//   2. the program's defines     e.g. "#define SHADOWS\n": variants of one shader, chosen once
//   3. common.glsl               helpers shared by all shaders (GLSL 3.30 has no #include)
//   4. "#line 1" + the file      so the driver's line numbers match the file's own lines
#include <GL/gl.h>

#include <string_view>

namespace tumble::render {

struct ShaderSource {
    std::string_view name; // for error messages, e.g. "lit.frag"
    std::string_view text; // GLSL without a #version line
};

// Looks up an embedded file from assets/shaders; throws RenderError if it is not there.
ShaderSource shader_asset(std::string_view file_name);

// A linked GL program object (move-only RAII). Needs a current GL context.
class ShaderProgram {
  public:
    ShaderProgram() = default;
    // Compiles and links; throws RenderError naming the failing shader, with the driver's log.
    // `defines` are "#define NAME\n" lines seen by both stages.
    ShaderProgram(ShaderSource vertex, ShaderSource fragment, std::string_view defines = {});
    ~ShaderProgram();
    ShaderProgram(ShaderProgram&& other) noexcept;
    ShaderProgram& operator=(ShaderProgram&& other) noexcept;

    GLuint id() const { return id_; }
    // Location of a uniform, or -1 if the program has none by that name (the GL ignores -1, so an
    // unused uniform that the compiler optimised away is harmless).
    GLint uniform(const char* name) const;

  private:
    GLuint id_ = 0;
};

} // namespace tumble::render
