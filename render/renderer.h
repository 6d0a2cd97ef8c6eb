#pragma once
// Headless renderer: an OSMesa (llvmpipe) OpenGL 3.3+ core context that draws a SceneView into
// an Image. No window, no display, no global state: everything lives in the Renderer object.
#include "render/image.h"
#include "render/render_error.h"
#include "render/scene_view.h"

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>

namespace tumble::render {

struct RenderOptions {
    int width = 1280;
    int height = 720;
    // Multisample anti-aliasing: coverage and depth samples per pixel (1 = none). Clamped to the
    // context's GL_MAX_SAMPLES (4 on llvmpipe); options() reports the count in use.
    int samples = 4;
    bool shadows = true;           // shadow map from the key light
    bool soft_shadows = true;      // edges that harden towards the contact (shadows only)
    bool ambient_occlusion = true; // bodies darken the ground and each other where they meet
    bool reflections = false;      // the bodies mirrored in the ground plane
    int shadow_map_size = 1024;    // texels per side at most (a small scene uses a smaller corner)
};

// What the last draw() did, for --stats and benchmarks.
struct FrameStats {
    std::uint64_t triangles = 0;        // seen by the camera (after culling, at their detail)
    std::uint64_t shadow_triangles = 0; // drawn into the shadow map
    int batches = 0;                    // instanced draw calls, both passes
    int instances = 0;                  // drawn by the camera
};

// Threading: GL contexts are current per thread. draw() makes this renderer's context current on
// the calling thread, so several renderers can share a thread; use each from one thread at a time.
// The shaders live in assets/shaders (embedded); the passes of a frame are listed in renderer.cpp.
class Renderer {
  public:
    // Creates the context and uploads shaders and meshes. Throws RenderError with a clear
    // message when OSMesa cannot give a 3.3 core context.
    explicit Renderer(const RenderOptions& options);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Draws one frame and reads it back into `out` (resized as needed), rows top-down. Pass the
    // same Image every frame and nothing is allocated. Same SceneView in, same pixels out.
    void draw(const SceneView& view, Image& out);

    const RenderOptions& options() const;
    const FrameStats& last_frame() const;
    std::string gl_renderer() const; // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
    std::string gl_version() const;  // GL_VERSION, e.g. "4.5 (Core Profile) Mesa 22.3.6"

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace tumble::render
