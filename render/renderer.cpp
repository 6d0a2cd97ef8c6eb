// The renderer: one frame is a short list of passes.
//
//   1. draw lists  cull, choose levels of detail, group instances into batches (draw_list.h)
//   2. shadow map  the casters' depth seen from the key light (shadow_map.h, shadow.vert/.frag)
//   3. clear       colour and depth of the (multisampled) target: no frame depends on the last
//   4. reflection  (optional) the bodies mirrored in the ground plane, dimmed by the floor's
//                  reflectance; the ground is then added over them (reflections)
//   5. scene       every batch, one instanced draw call each, lit (lit.vert / lit.frag)
//   6. occlusion   the ground decals of ambient occlusion (occlusion_decals.h)
//   7. sky         one screen-covering triangle on the far plane (sky.vert / sky.frag); drawn
//                  after the scene so the depth test skips every pixel an object already covers
//   7b. lines      translucent surfaces' far sides (glass.h), world-space polylines as ribbons,
//                  behind bodies where they pass behind (line_ribbons.h), the surfaces' near
//                  sides, and the canvas (charts, legends) over everything, all multisampled
//   8. resolve     average each pixel's MSAA samples into the single-sample target
//   9. overlay     text in a corner (text_overlay.h), after the resolve: it needs no MSAA
//  10. read back   glReadPixels into the caller's Image, flipped to top-down rows
// Everything lives in Renderer::Impl: no globals.
#include "render/renderer.h"

#include "render/batches.h"
#include "render/camera.h"
#include "render/color.h"
#include "render/draw_list.h"
#include "render/framebuffer.h"
#include "render/gl_context.h"
#include "render/glass.h"
#include "render/line_ribbons.h"
#include "render/mesh.h"
#include "render/occlusion_decals.h"
#include "render/shader.h"
#include "render/shadow_map.h"
#include "render/text_overlay.h"

#include <GL/glext.h>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>
#include <vector>

namespace tumble::render {
namespace {

// Uniform locations of lit.vert + lit.frag, looked up once.
struct LitUniforms {
    GLint view_proj, camera_pos, light_dir, light_color, ambient, horizon, zenith;
    GLint shadow_matrix, normal_offset, shadow_map, shadow_texel, shadow_depth, penumbra_scale;
    GLint clip_plane, mirror;

    explicit LitUniforms(const ShaderProgram& p)
        : view_proj(p.uniform("u_view_proj")), camera_pos(p.uniform("u_camera_pos")),
          light_dir(p.uniform("u_light_dir")), light_color(p.uniform("u_light_color")),
          ambient(p.uniform("u_ambient")), horizon(p.uniform("u_horizon")),
          zenith(p.uniform("u_zenith")), shadow_matrix(p.uniform("u_shadow_matrix")),
          normal_offset(p.uniform("u_normal_offset")), shadow_map(p.uniform("u_shadow_map")),
          shadow_texel(p.uniform("u_shadow_texel")), shadow_depth(p.uniform("u_shadow_depth")),
          penumbra_scale(p.uniform("u_penumbra_scale")), clip_plane(p.uniform("u_clip_plane")),
          mirror(p.uniform("u_mirror")) {}
};

struct SkyUniforms {
    GLint inv_view_proj, camera_pos, horizon, zenith;

    explicit SkyUniforms(const ShaderProgram& p)
        : inv_view_proj(p.uniform("u_inv_view_proj")), camera_pos(p.uniform("u_camera_pos")),
          horizon(p.uniform("u_horizon")), zenith(p.uniform("u_zenith")) {}
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

// Checks the image size against the GL's limit and settles the sample count.
RenderOptions checked(RenderOptions o) {
    GLint max_size = 0, max_samples = 1;
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
    glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
    if (o.width <= 0 || o.height <= 0 || o.width > max_size || o.height > max_size) {
        throw RenderError("image size " + std::to_string(o.width) + "x" + std::to_string(o.height) +
                          " is outside 1.." + std::to_string(max_size));
    }
    o.samples = std::clamp(o.samples, 1, std::max(1, int(max_samples)));
    if (o.shadow_map_size < 16 || o.shadow_map_size > max_size)
        throw RenderError("shadow map size " + std::to_string(o.shadow_map_size) +
                          " is outside 16.." + std::to_string(max_size));
    return o;
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

std::string lit_defines(const RenderOptions& o) {
    std::string d;
    if (o.shadows) d += "#define SHADOWS\n";
    if (o.shadows && o.soft_shadows)
        d += "#extension GL_ARB_texture_gather : require\n#define SOFT_SHADOWS\n";
    if (o.ambient_occlusion) d += "#define AMBIENT_OCCLUSION\n";
    return d;
}

// The ground plane that reflections mirror in: the first plane of the view, as a point on it
// and its unit normal. None: no reflection.
std::optional<std::pair<glm::vec3, glm::vec3>> mirror_plane(const SceneView& view) {
    for (const Instance& in : view.instances) {
        if (in.mesh != MeshKind::Plane) continue;
        const glm::vec3 n = glm::cross(glm::vec3(in.transform[0]), glm::vec3(in.transform[1]));
        if (glm::length(n) == 0.0f) continue;
        return std::pair{glm::vec3(in.transform[3]), glm::normalize(n)};
    }
    return std::nullopt;
}

// Reflection in the plane through `p` with unit normal `n`: x -> x - 2 ((x - p) . n) n.
glm::mat4 mirror_matrix(glm::vec3 p, glm::vec3 n) {
    glm::mat4 m(1.0f);
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) m[c][r] -= 2.0f * n[c] * n[r];
    m[3] = glm::vec4(2.0f * glm::dot(p, n) * n, 1.0f);
    return m;
}

} // namespace

struct Renderer::Impl {
    GlContext context; // declared first: created before, and destroyed after, every GL object
    RenderOptions options;
    Framebuffer target;              // single-sample: resolved image, overlay, read back
    std::optional<Framebuffer> msaa; // when options.samples > 1
    ShaderProgram lit, sky;
    std::optional<ShaderProgram> shadow_program;
    LitUniforms lit_uniforms;
    SkyUniforms sky_uniforms;
    GLint shadow_light_view_proj = -1;
    MeshLibrary library;
    CustomMeshCache custom_meshes;
    InstanceBuffer camera_instances, shadow_instances;
    std::optional<ShadowMap> shadow_map;
    std::optional<OcclusionDecals> decals;
    std::unique_ptr<TextOverlay> overlay; // made on first use
    std::unique_ptr<LineRibbons> ribbons; // made on first use
    std::unique_ptr<GlassPass> glass;     // made on first use
    DrawLists lists;
    FrameStats stats;
    GLuint empty_vao = 0; // core profile draws need a vertex array, even one with no attributes

    explicit Impl(const RenderOptions& o)
        : options(checked(o)), target(options.width, options.height),
          lit(shader_asset("lit.vert"), shader_asset("lit.frag"), lit_defines(options)),
          sky(shader_asset("sky.vert"), shader_asset("sky.frag")), lit_uniforms(lit),
          sky_uniforms(sky) {
        if (options.samples > 1) msaa.emplace(options.width, options.height, options.samples);
        if (options.shadows) {
            shadow_program.emplace(shader_asset("shadow.vert"), shader_asset("shadow.frag"));
            shadow_light_view_proj = shadow_program->uniform("u_light_view_proj");
            shadow_map.emplace(options.shadow_map_size);
        }
        if (options.ambient_occlusion) decals.emplace();
        glGenVertexArrays(1, &empty_vao);
        check_gl("while setting up the renderer");
    }

    // Member destructors delete GL objects, which needs this context current on this thread.
    ~Impl() {
        context.make_current();
        glDeleteVertexArrays(1, &empty_vao);
    }

    void shadow_pass();
    void set_lit_uniforms(const SceneView& view, const FrameMatrices& m);
    void reflection_pass(const SceneView& view, const FrameMatrices& m);
    void scene_pass(const SceneView& view, const FrameMatrices& m);
    void sky_pass(const SceneView& view, const FrameMatrices& m);
    void construction_pass(const SceneView& view, const FrameMatrices& m);
};

void Renderer::Impl::shadow_pass() {
    // Cleared even with no casters: then everything reads as lit.
    shadow_map->begin_pass(lists.light.empty ? options.shadow_map_size : lists.light.map_size);
    if (lists.light.empty) return;
    shadow_instances.upload(lists.shadow);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    // A small slope-scaled offset for the two-sided meshes, whose lit faces are in the map too.
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.5f, 2.0f);
    glUseProgram(shadow_program->id());
    glUniformMatrix4fv(shadow_light_view_proj, 1, GL_FALSE, glm::value_ptr(lists.light.view_proj));
    shadow_instances.draw(lists.shadow, GL_FRONT); // closed meshes: back faces only
    glDisable(GL_POLYGON_OFFSET_FILL);
}

void Renderer::Impl::set_lit_uniforms(const SceneView& view, const FrameMatrices& m) {
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
    const SkyColours sky = sky_colours(view.background);
    glUniform3fv(u.horizon, 1, glm::value_ptr(sky.horizon));
    glUniform3fv(u.zenith, 1, glm::value_ptr(sky.zenith));
    glUniform1f(u.mirror, 0.0f);
    glUniform4f(u.clip_plane, 0.0f, 0.0f, 0.0f, 1.0f);
    if (options.shadows) {
        const LightFrame& light = lists.light;
        // With no casters the identity puts every point at depth <= 1: all lit.
        const glm::mat4 lookup = light.empty ? glm::mat4(1.0f) : shadow_map->lookup_matrix(light);
        glUniformMatrix4fv(u.shadow_matrix, 1, GL_FALSE, glm::value_ptr(lookup));
        glUniform1f(u.normal_offset, 1.5f * light.texel_size);
        glUniform1f(u.shadow_texel, 1.0f / float(options.shadow_map_size));
        glUniform1i(u.shadow_map, 1);
        shadow_map->bind_texture(GL_TEXTURE1);
        if (options.soft_shadows) {
            // Penumbra width in texels per unit of map depth: 2 tan(angle / 2) x depth range in
            // metres / texel size in metres (lit.frag, light_visibility).
            const float half_angle = 0.5f * glm::radians(std::max(view.light.angle_deg, 0.0f));
            const float scale =
                light.empty ? 0.0f
                            : 2.0f * std::tan(half_angle) * light.depth_range / light.texel_size;
            glUniform1f(u.penumbra_scale, scale);
            glUniform1i(u.shadow_depth, 2);
            shadow_map->bind_raw_depths(2);
        }
    }
}

void Renderer::Impl::reflection_pass(const SceneView& view, const FrameMatrices& m) {
    const auto plane = mirror_plane(view);
    if (!plane) return;
    const auto [p, n] = *plane;
    const glm::mat4 mirror = mirror_matrix(p, n);
    // The mirrored world seen by the camera is the world seen by the mirrored camera: the
    // bodies keep their own positions, normals and shading; only where they land on the screen
    // (and the eye their highlights are seen from) moves. Mirroring turns clockwise winding
    // into counter-clockwise, so front faces are the clockwise ones for this pass. Whatever of
    // a body reaches below the plane is clipped away: it would show above the floor.
    const LitUniforms& u = lit_uniforms;
    const glm::mat4 vp = m.view_proj * mirror;
    glUniformMatrix4fv(u.view_proj, 1, GL_FALSE, glm::value_ptr(vp));
    const glm::vec3 eye = glm::vec3(mirror * glm::vec4(view.camera.position, 1.0f));
    glUniform3fv(u.camera_pos, 1, glm::value_ptr(eye));
    glUniform4f(u.clip_plane, n.x, n.y, n.z, -glm::dot(n, p));
    glUniform1f(u.mirror, 1.0f);
    glEnable(GL_CLIP_DISTANCE0);
    glFrontFace(GL_CW);
    camera_instances.draw(lists.camera, GL_BACK, InstanceBuffer::Select::ExceptRank, kGroundRank);
    glFrontFace(GL_CCW);
    glDisable(GL_CLIP_DISTANCE0);
    glUniformMatrix4fv(u.view_proj, 1, GL_FALSE, glm::value_ptr(m.view_proj));
    glUniform3fv(u.camera_pos, 1, glm::value_ptr(view.camera.position));
    glUniform4f(u.clip_plane, 0.0f, 0.0f, 0.0f, 1.0f);
    glUniform1f(u.mirror, 0.0f);
}

void Renderer::Impl::scene_pass(const SceneView& view, const FrameMatrices& m) {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    set_lit_uniforms(view, m);
    camera_instances.upload(lists.camera);
    if (!options.reflections) {
        camera_instances.draw(lists.camera, GL_BACK);
    } else {
        reflection_pass(view, m);
        // The bodies, then the ground over the reflections: where a reflection left R in alpha
        // the floor keeps 1 - R of its colour and the reflection (premultiplied) adds the rest;
        // elsewhere alpha is the clear's 0 and the floor is drawn as it is.
        camera_instances.draw(lists.camera, GL_BACK, InstanceBuffer::Select::ExceptRank,
                              kGroundRank);
        glEnable(GL_BLEND);
        glBlendFunc(GL_ONE_MINUS_DST_ALPHA, GL_ONE);
        camera_instances.draw(lists.camera, GL_BACK, InstanceBuffer::Select::Rank, kGroundRank);
        glDisable(GL_BLEND);
    }
    if (decals) decals->draw(lists.decals, library.plane, m.view_proj, view.camera.position);
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
    const SkyColours sky = sky_colours(view.background);
    glUniform3fv(sky_uniforms.horizon, 1, glm::value_ptr(sky.horizon));
    glUniform3fv(sky_uniforms.zenith, 1, glm::value_ptr(sky.zenith));
    glBindVertexArray(empty_vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDepthMask(GL_TRUE);
}

void Renderer::Impl::construction_pass(const SceneView& view, const FrameMatrices& m) {
    if (!view.glass.empty() && !glass) glass = std::make_unique<GlassPass>();
    if (glass)
        glass->draw(view.glass, GlassPass::Half::Far, library, m.view_proj, view.camera,
                    view.light);
    if (!view.lines.strips.empty()) {
        if (!ribbons) ribbons = std::make_unique<LineRibbons>();
        ribbons->draw(view.lines, m.view_proj, options.width, options.height);
    }
    if (glass)
        glass->draw(view.glass, GlassPass::Half::Near, library, m.view_proj, view.camera,
                    view.light);
}

Renderer::Renderer(const RenderOptions& options) : impl_(std::make_unique<Impl>(options)) {}

Renderer::~Renderer() = default;

void Renderer::draw(const SceneView& view, Image& out) {
    Impl& r = *impl_;
    r.context.make_current();
    const RenderOptions& o = r.options;
    const FrameMatrices m = frame_matrices(view.camera, float(o.width) / float(o.height));
    DrawSettings settings;
    settings.view_proj = m.view_proj;
    settings.height = o.height;
    settings.shadows = o.shadows;
    settings.shadow_map_size = o.shadow_map_size;
    settings.ambient_occlusion = o.ambient_occlusion;
    build_draw_lists(view, settings, r.library, r.custom_meshes.resolve(view), r.lists);
    if (o.shadows) r.shadow_pass();

    const Framebuffer& main = r.msaa ? *r.msaa : r.target;
    main.bind();
    // The sky pass paints every pixel nothing else covers, so the clear colour never shows. With
    // reflections it is (0, 0, 0, 0): alpha 0 tells the ground where no reflection was drawn,
    // and black adds nothing there.
    if (o.reflections)
        glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    else
        glClearColor(view.background.r, view.background.g, view.background.b, 1.0f);
    glClearDepth(1.0);
    glDepthMask(GL_TRUE); // glClear respects the depth write mask
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    r.scene_pass(view, m);
    r.sky_pass(view, m);
    r.construction_pass(view, m);
    if (!view.canvas.empty()) {
        if (!r.overlay) r.overlay = std::make_unique<TextOverlay>(o.width, o.height);
        r.overlay->draw(view.canvas, o.width, o.height);
    }
    if (r.msaa) r.msaa->resolve_into(r.target);
    if (!view.overlay.empty()) {
        if (!r.overlay) r.overlay = std::make_unique<TextOverlay>(o.width, o.height);
        r.target.bind();
        r.overlay->draw(view.overlay, view.overlay_at, o.width, o.height);
    }
    r.target.read_rgb(out);
    check_gl("while drawing a frame");

    r.stats.triangles = r.lists.camera.triangles();
    r.stats.shadow_triangles = r.lists.light.empty ? 0 : r.lists.shadow.triangles();
    r.stats.batches = int(r.lists.camera.batches().size() +
                          (r.lists.light.empty ? 0 : r.lists.shadow.batches().size()));
    r.stats.instances = int(r.lists.camera.data().size());
}

const RenderOptions& Renderer::options() const {
    return impl_->options;
}
const FrameStats& Renderer::last_frame() const {
    return impl_->stats;
}
std::string Renderer::gl_renderer() const {
    return impl_->context.renderer();
}
std::string Renderer::gl_version() const {
    return impl_->context.version();
}

} // namespace tumble::render
