#include "render/shader.h"

#include "render/assets.h"
#include "render/render_error.h"

#include <GL/glext.h>

#include <string>
#include <utility>

namespace tumble::render {
namespace {

constexpr std::string_view kVersion = "#version 330 core\n";
constexpr std::string_view kCommonName = "common.glsl";

// The info log of a shader or program: what the driver says went wrong.
std::string shader_log(GLuint shader) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    return log.c_str(); // drop the terminating NUL
}

std::string program_log(GLuint program) {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
    glGetProgramInfoLog(program, length, nullptr, log.data());
    return log.c_str();
}

// Compiles one stage from the version line, the shared helpers and the file (see shader.h).
GLuint compile(GLenum stage, ShaderSource source, std::string_view defines) {
    const std::string_view common = shader_asset(kCommonName).text;
    const std::string_view line_reset = "\n#line 1\n";
    if (defines.data() == nullptr) defines = ""; // a default string_view has no storage at all
    const char* parts[] = {kVersion.data(), defines.data(), common.data(), line_reset.data(),
                           source.text.data()};
    const GLint lengths[] = {GLint(kVersion.size()), GLint(defines.size()), GLint(common.size()),
                             GLint(line_reset.size()), GLint(source.text.size())};
    const GLuint shader = glCreateShader(stage);
    glShaderSource(shader, 5, parts, lengths);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        const std::string log = shader_log(shader);
        glDeleteShader(shader);
        throw RenderError("shader '" + std::string(source.name) + "' failed to compile (line " +
                          "numbers are the file's own; errors before line 1 are in " +
                          std::string(kCommonName) + "):\n" + log);
    }
    return shader;
}

} // namespace

ShaderSource shader_asset(std::string_view file_name) {
    const std::string_view text = assets::find(file_name);
    if (text.empty()) {
        throw RenderError("shader '" + std::string(file_name) +
                          "' is not embedded in the binary (expected assets/shaders/" +
                          std::string(file_name) + ")");
    }
    return {file_name, text};
}

ShaderProgram::ShaderProgram(ShaderSource vertex, ShaderSource fragment, std::string_view defines) {
    const GLuint vs = compile(GL_VERTEX_SHADER, vertex, defines);
    GLuint fs = 0;
    try {
        fs = compile(GL_FRAGMENT_SHADER, fragment, defines);
    } catch (...) {
        glDeleteShader(vs);
        throw;
    }
    id_ = glCreateProgram();
    glAttachShader(id_, vs);
    glAttachShader(id_, fs);
    glLinkProgram(id_);
    // The program keeps the compiled code; the shader objects can go as soon as it is linked.
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = GL_FALSE;
    glGetProgramiv(id_, GL_LINK_STATUS, &ok);
    if (!ok) {
        const std::string log = program_log(id_);
        glDeleteProgram(id_);
        id_ = 0;
        throw RenderError("program '" + std::string(vertex.name) + " + " +
                          std::string(fragment.name) + "' failed to link:\n" + log);
    }
}

ShaderProgram::~ShaderProgram() {
    if (id_) glDeleteProgram(id_);
}

ShaderProgram::ShaderProgram(ShaderProgram&& other) noexcept : id_(std::exchange(other.id_, 0)) {}

ShaderProgram& ShaderProgram::operator=(ShaderProgram&& other) noexcept {
    if (this != &other) {
        if (id_) glDeleteProgram(id_);
        id_ = std::exchange(other.id_, 0);
    }
    return *this;
}

GLint ShaderProgram::uniform(const char* name) const {
    return glGetUniformLocation(id_, name);
}

} // namespace tumble::render
