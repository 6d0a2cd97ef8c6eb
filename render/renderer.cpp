// The renderer: one frame is a short list of passes over an off-screen framebuffer.
//
//   1. clear       colour and depth, so a frame never depends on the one before
//   2. scene pass  every instance, Blinn-Phong lit (lit.vert / lit.frag), grouped by mesh kind
//   3. sky pass    one screen-covering triangle on the far plane (sky.vert / sky.frag); drawn
//                  last so the depth test skips every pixel an object already covers
//   4. read back   glReadPixels into the caller's Image, flipped to top-down rows
//
// Later passes slot in between: a shadow pass (depth from the light) before 2, an MSAA resolve
// between 3 and 4, a text overlay after 3. Everything lives in Renderer::Impl: no globals.
#include "render/renderer.h"

#include "render/camera.h"
#include "render/framebuffer.h"
#include "render/gl_context.h"
#include "render/mesh.h"
#include "render/shader.h"

#include <GL/glext.h>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <array>
#include <cstdio>
#include <memory>
#include <vector>

namespace tumble::render {
namespace {

// The built-in unit meshes, uploaded once; the array is indexed by MeshKind.
constexpr std::array kBuiltinKinds{MeshKind::Sphere, MeshKind::Box, MeshKind::Plane,
                                   MeshKind::Cylinder};
// Drawing order: solid bodies first, the ground last (its hidden pixels then fail the depth test
// before they are shaded).
constexpr std::array kDrawOrder{MeshKind::Sphere, MeshKind::Box, MeshKind::Cylinder,
                                MeshKind::Custom, MeshKind::Plane};

// How each kind of mesh looks besides its colour. Closed meshes (sphere, box) cull their back
// faces, which are always hidden; the plane is seen from both sides.
struct Material {
    float specular;  // highlight strength
    float shininess; // highlight sharpness
    bool checker;    // ground checkerboard
    bool closed;     // cull back faces
};

Material material_of(MeshKind kind) {
    switch (kind) {
    case MeshKind::Sphere:
        return {0.35f, 60.0f, false, true};
    case MeshKind::Box:
        return {0.25f, 40.0f, false, true};
    case MeshKind::Plane:
        return {0.04f, 16.0f, true, false};
    case MeshKind::Cylinder:
        return {0.3f, 50.0f, false, true};
    case MeshKind::Custom: // two-sided: an OBJ file's winding is not to be trusted
        return {0.25f, 40.0f, false, false};
    }
    return {0.0f, 1.0f, false, false};
}

// Uniform locations of lit.vert + lit.frag, looked up once.
struct LitUniforms {
    GLint model, normal_matrix, view_proj, color, checker, specular, shininess;
    GLint camera_pos, light_dir, light_color, ambient, background;

    explicit LitUniforms(const ShaderProgram& p)
        : model(p.uniform("u_model")), normal_matrix(p.uniform("u_normal_matrix")),
          view_proj(p.uniform("u_view_proj")), color(p.uniform("u_color")),
          checker(p.uniform("u_checker")), specular(p.uniform("u_specular")),
          shininess(p.uniform("u_shininess")), camera_pos(p.uniform("u_camera_pos")),
          light_dir(p.uniform("u_light_dir")), light_color(p.uniform("u_light_color")),
          ambient(p.uniform("u_ambient")), background(p.uniform("u_background")) {}
};

struct SkyUniforms {
    GLint inv_view_proj, camera_pos, background;

    explicit SkyUniforms(const ShaderProgram& p)
        : inv_view_proj(p.uniform("u_inv_view_proj")), camera_pos(p.uniform("u_camera_pos")),
          background(p.uniform("u_background")) {}
};

// The camera's matrices for one frame, computed once and shared by the passes.
struct FrameMatrices {
    glm::mat4 view_proj;
    glm::mat4 inv_view_proj;
};

FrameMatrices frame_matrices(const Camera& camera, float aspect) {
    const glm::mat4 vp = projection_matrix(camera, aspect) * view_matrix(camera);
    return {vp, glm::inverse(vp)};
}

// Throws if the GL recorded an error since the last check (an error means a bug in this file).
void check_gl(const char* where) {
    const GLenum error = glGetError();
    if (error == GL_NO_ERROR) return;
    while (glGetError() != GL_NO_ERROR) {
    } // drain the remaining flags
    char code[16];
    std::snprintf(code, sizeof code, "0x%04X", error);
    throw RenderError(std::string("OpenGL error ") + code + " " + where);
}

// The framebuffer every pass draws into, after checking the GL can make one that size.
Framebuffer make_target(const RenderOptions& o) {
    GLint max_size = 0;
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
    if (o.width <= 0 || o.height <= 0 || o.width > max_size || o.height > max_size) {
        throw RenderError("image size " + std::to_string(o.width) + "x" + std::to_string(o.height) +
                          " is outside 1.." + std::to_string(max_size));
    }
    return Framebuffer(o.width, o.height);
}

// GPU copies of the SceneView's custom meshes, keyed by the MeshData they were made from. An
// entry lives while its MeshData does (weak_ptr), so a freed mesh whose address is reused by a
// new one is never mistaken for it.
class CustomMeshCache {
  public:
    // The GPU mesh of every view.meshes[i], uploading the ones not seen before. The pointers stay
    // valid until the next call.
    const std::vector<const GpuMesh*>& resolve(const SceneView& view) {
        std::erase_if(entries_, [](const Entry& e) { return e.source.expired(); });
        resolved_.clear();
        for (const auto& mesh : view.meshes) {
            if (!mesh) throw RenderError("SceneView::meshes holds a null mesh");
            Entry* found = nullptr;
            for (Entry& e : entries_)
                if (e.key == mesh.get()) found = &e;
            if (!found) {
                entries_.push_back({mesh, mesh.get(), std::make_unique<GpuMesh>(*mesh)});
                found = &entries_.back();
            }
            resolved_.push_back(found->gpu.get());
        }
        return resolved_;
    }

  private:
    struct Entry {
        std::weak_ptr<const MeshData> source;
        const MeshData* key;
        std::unique_ptr<GpuMesh> gpu;
    };
    std::vector<Entry> entries_;
    std::vector<const GpuMesh*> resolved_;
};

} // namespace

struct Renderer::Impl {
    RenderOptions options;
    GlContext context; // declared first: created before, and destroyed after, every GL object
    Framebuffer target;
    ShaderProgram lit;
    ShaderProgram sky;
    LitUniforms lit_uniforms;
    SkyUniforms sky_uniforms;
    std::array<GpuMesh, kBuiltinKinds.size()> meshes; // indexed by MeshKind
    CustomMeshCache custom_meshes;
    GLuint empty_vao = 0; // core profile draws need a vertex array, even one with no attributes

    explicit Impl(const RenderOptions& o)
        : options(o), target(make_target(o)),
          lit(shader_asset("lit.vert"), shader_asset("lit.frag")),
          sky(shader_asset("sky.vert"), shader_asset("sky.frag")), lit_uniforms(lit),
          sky_uniforms(sky) {
        for (MeshKind kind : kBuiltinKinds) meshes[std::size_t(kind)] = GpuMesh(make_mesh(kind));
        glGenVertexArrays(1, &empty_vao);
        check_gl("while setting up the renderer");
    }

    // Member destructors delete GL objects, which needs this context current on this thread.
    ~Impl() {
        context.make_current();
        glDeleteVertexArrays(1, &empty_vao);
    }

    void clear(const SceneView& view);
    void scene_pass(const SceneView& view, const FrameMatrices& m);
    void draw_kind(const SceneView& view, MeshKind kind, const std::vector<const GpuMesh*>& custom);
    void draw_instance(const Instance& instance, const GpuMesh& mesh);
    void sky_pass(const SceneView& view, const FrameMatrices& m);
};

void Renderer::Impl::clear(const SceneView& view) {
    target.bind();
    glClearColor(view.background.r, view.background.g, view.background.b, 1.0f);
    glClearDepth(1.0);
    glDepthMask(GL_TRUE); // glClear respects the depth write mask
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

void Renderer::Impl::scene_pass(const SceneView& view, const FrameMatrices& m) {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glUseProgram(lit.id());
    // Per-frame uniforms: the camera and the light are the same for every instance.
    const LitUniforms& u = lit_uniforms;
    glUniformMatrix4fv(u.view_proj, 1, GL_FALSE, glm::value_ptr(m.view_proj));
    glUniform3fv(u.camera_pos, 1, glm::value_ptr(view.camera.position));
    const float length = glm::length(view.light.direction);
    const glm::vec3 light_dir = length > 0.0f ? view.light.direction / length : glm::vec3{0, 0, -1};
    glUniform3fv(u.light_dir, 1, glm::value_ptr(light_dir));
    glUniform3fv(u.light_color, 1, glm::value_ptr(view.light.color));
    glUniform1f(u.ambient, view.light.ambient);
    glUniform3fv(u.background, 1, glm::value_ptr(view.background));
    const std::vector<const GpuMesh*>& custom = custom_meshes.resolve(view);
    for (MeshKind kind : kDrawOrder) draw_kind(view, kind, custom);
}

// Draws every instance of one mesh kind: the material (and for built-in kinds the mesh) is bound
// once for all of them.
void Renderer::Impl::draw_kind(const SceneView& view, MeshKind kind,
                               const std::vector<const GpuMesh*>& custom) {
    const Material mat = material_of(kind);
    const LitUniforms& u = lit_uniforms;
    glUniform1f(u.specular, mat.specular);
    glUniform1f(u.shininess, mat.shininess);
    glUniform1i(u.checker, mat.checker ? 1 : 0);
    if (mat.closed)
        glEnable(GL_CULL_FACE);
    else
        glDisable(GL_CULL_FACE);
    if (kind == MeshKind::Custom) {
        for (const Instance& instance : view.instances) {
            if (instance.mesh != kind) continue;
            if (instance.mesh_id >= custom.size())
                throw RenderError("instance uses custom mesh " + std::to_string(instance.mesh_id) +
                                  " but the view has " + std::to_string(custom.size()));
            custom[instance.mesh_id]->bind();
            draw_instance(instance, *custom[instance.mesh_id]);
        }
        return;
    }
    const GpuMesh& mesh = meshes[std::size_t(kind)];
    mesh.bind();
    for (const Instance& instance : view.instances)
        if (instance.mesh == kind) draw_instance(instance, mesh);
}

void Renderer::Impl::draw_instance(const Instance& instance, const GpuMesh& mesh) {
    const LitUniforms& u = lit_uniforms;
    // Normals transform by the inverse-transpose: a box squashed in z must get normals
    // stretched in z to stay perpendicular to its faces.
    const glm::mat3 normal_matrix = glm::inverseTranspose(glm::mat3(instance.transform));
    glUniformMatrix4fv(u.model, 1, GL_FALSE, glm::value_ptr(instance.transform));
    glUniformMatrix3fv(u.normal_matrix, 1, GL_FALSE, glm::value_ptr(normal_matrix));
    glUniform3fv(u.color, 1, glm::value_ptr(instance.color));
    mesh.draw();
}

void Renderer::Impl::sky_pass(const SceneView& view, const FrameMatrices& m) {
    // The sky sits at depth 1.0, equal to the cleared depth: LEQUAL lets it through exactly
    // where nothing was drawn. It writes no depth and is never culled.
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    glUseProgram(sky.id());
    glUniformMatrix4fv(sky_uniforms.inv_view_proj, 1, GL_FALSE, glm::value_ptr(m.inv_view_proj));
    glUniform3fv(sky_uniforms.camera_pos, 1, glm::value_ptr(view.camera.position));
    glUniform3fv(sky_uniforms.background, 1, glm::value_ptr(view.background));
    glBindVertexArray(empty_vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDepthMask(GL_TRUE);
}

Renderer::Renderer(const RenderOptions& options) : impl_(std::make_unique<Impl>(options)) {}

Renderer::~Renderer() = default;

void Renderer::draw(const SceneView& view, Image& out) {
    Impl& r = *impl_;
    r.context.make_current();
    const float aspect = float(r.options.width) / float(r.options.height);
    const FrameMatrices m = frame_matrices(view.camera, aspect);
    r.clear(view);
    r.scene_pass(view, m);
    r.sky_pass(view, m);
    r.target.read_rgb(out);
    check_gl("while drawing a frame");
}

const RenderOptions& Renderer::options() const {
    return impl_->options;
}
std::string Renderer::gl_renderer() const {
    return impl_->context.renderer();
}
std::string Renderer::gl_version() const {
    return impl_->context.version();
}

} // namespace tumble::render
