#include "app/view/overlay_layout.h"

#include "render/camera.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tumble::app {
namespace {

constexpr glm::vec4 kLegendPanel{0.05f, 0.06f, 0.08f, 0.55f}; // as the text overlay's panel
constexpr glm::vec4 kLegendText{1.0f, 1.0f, 1.0f, 0.95f};

// Radius of the sphere about the unit mesh's origin that holds it (scene_view.h's unit meshes).
float unit_radius(const render::Instance& in, const render::SceneView& view) {
    switch (in.mesh) {
    case render::MeshKind::Sphere:
        return 1.0f;
    case render::MeshKind::Box:
        return std::sqrt(3.0f);
    case render::MeshKind::Cylinder:
        return std::sqrt(2.0f);
    case render::MeshKind::Plane:
        return 0.0f;
    case render::MeshKind::Custom:
        break;
    }
    float r = 0.0f;
    if (in.mesh_id < view.meshes.size() && view.meshes[in.mesh_id])
        for (const render::Vertex& v : view.meshes[in.mesh_id]->vertices)
            r = std::max(r, glm::length(v.position));
    return r;
}

// The screen rectangle of world points. False when one is behind the camera.
bool project_points(const glm::mat4& view_proj, const glm::vec3* points, int count, int width,
                    int height, ScreenBox& out) {
    out.min = glm::vec2(std::numeric_limits<float>::max());
    out.max = glm::vec2(std::numeric_limits<float>::lowest());
    for (int k = 0; k < count; ++k) {
        const glm::vec4 clip = view_proj * glm::vec4(points[k], 1.0f);
        if (clip.w <= 1e-6f) return false;
        const glm::vec2 ndc = glm::vec2(clip) / clip.w;
        const glm::vec2 px((ndc.x * 0.5f + 0.5f) * float(width),
                           (0.5f - ndc.y * 0.5f) * float(height));
        out.min = glm::min(out.min, px);
        out.max = glm::max(out.max, px);
    }
    out.min = glm::clamp(out.min, glm::vec2(0.0f), glm::vec2(float(width), float(height)));
    out.max = glm::clamp(out.max, glm::vec2(0.0f), glm::vec2(float(width), float(height)));
    return out.area() > 0.0f;
}

// The screen rectangle of a world sphere: its bounding cube's corners projected.
bool project_sphere(const glm::mat4& view_proj, glm::vec3 centre, float radius, int width,
                    int height, ScreenBox& out) {
    glm::vec3 corners[8];
    for (int k = 0; k < 8; ++k)
        corners[k] = centre + radius * glm::vec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1);
    return project_points(view_proj, corners, 8, width, height, out);
}

float max_scale(const glm::mat4& t) {
    return std::max(
        {glm::length(glm::vec3(t[0])), glm::length(glm::vec3(t[1])), glm::length(glm::vec3(t[2]))});
}

} // namespace

float ScreenBox::area() const {
    return std::max(0.0f, max.x - min.x) * std::max(0.0f, max.y - min.y);
}

float overlap(const ScreenBox& a, const ScreenBox& b) {
    return ScreenBox{glm::max(a.min, b.min), glm::min(a.max, b.max)}.area();
}

std::vector<ScreenBox> keep_visible(const render::SceneView& view, int width, int height) {
    const glm::mat4 vp = render::projection_matrix(view.camera, float(width) / float(height)) *
                         render::view_matrix(view.camera);
    std::vector<ScreenBox> out;
    ScreenBox box;
    for (const render::Instance& in : view.instances) {
        if (in.mesh == render::MeshKind::Plane) continue;
        const float r = unit_radius(in, view) * max_scale(in.transform);
        if (project_sphere(vp, glm::vec3(in.transform[3]), r, width, height, box))
            out.push_back(box);
    }
    for (const render::Glass& g : view.glass) {
        bool seen = false;
        if (g.mesh == render::MeshKind::Plane) { // a flat square: its corners, seen at a slant
            glm::vec3 corners[4];
            for (int k = 0; k < 4; ++k)
                corners[k] =
                    glm::vec3(g.transform * glm::vec4(k & 1 ? 1 : -1, k & 2 ? 1 : -1, 0, 1));
            seen = project_points(vp, corners, 4, width, height, box);
        } else {
            const float unit = g.mesh == render::MeshKind::Sphere ? 1.0f : std::sqrt(3.0f);
            seen = project_sphere(vp, glm::vec3(g.transform[3]), unit * max_scale(g.transform),
                                  width, height, box);
        }
        if (seen) out.push_back(box);
    }
    return out;
}

OverlayLayout::OverlayLayout(int width, int height, std::vector<ScreenBox> keep)
    : width_(width), height_(height), font_(render::overlay_font(width, height)),
      keep_(std::move(keep)) {}

bool OverlayLayout::cramped(glm::vec2 size) const {
    return size.x > 0.45f * float(width_) || size.y > 0.35f * float(height_);
}

ScreenBox OverlayLayout::at_corner(Corner c, glm::vec2 size) const {
    const float m = font_.margin(), gap = std::round(0.5f * m);
    const float used = stacked_[std::size_t(c)];
    const float offset = used > 0.0f ? used + gap : 0.0f;
    const bool left = c == Corner::TopLeft || c == Corner::BottomLeft;
    const bool top = c == Corner::TopLeft || c == Corner::TopRight;
    const float x = left ? m : float(width_) - m - size.x;
    const float y = top ? m + offset : float(height_) - m - offset - size.y;
    return {{x, y}, {x + size.x, y + size.y}};
}

double OverlayLayout::cost(const ScreenBox& b) const {
    // Off the image, or over another panel: never, if anywhere else will do.
    double c = 0.0;
    if (b.min.x < 0.0f || b.min.y < 0.0f || b.max.x > float(width_) || b.max.y > float(height_))
        c += 1e12;
    for (const ScreenBox& p : placed_) c += 1e9 * double(overlap(b, p) > 0.0f);
    for (const ScreenBox& k : keep_) c += double(overlap(b, k));
    return c;
}

ScreenBox OverlayLayout::place(glm::vec2 size, std::initializer_list<Corner> allowed) {
    Corner best = *allowed.begin();
    double best_cost = std::numeric_limits<double>::infinity();
    for (Corner c : allowed) {
        const double k = cost(at_corner(c, size));
        if (k < best_cost) best = c, best_cost = k;
    }
    const ScreenBox box = at_corner(best, size);
    float& used = stacked_[std::size_t(best)];
    used += (used > 0.0f ? std::round(0.5f * font_.margin()) : 0.0f) + size.y;
    placed_.push_back(box);
    return box;
}

glm::vec2 legend_size(const std::vector<LegendItem>& items, const render::OverlayFont& font) {
    std::size_t columns = 0;
    for (const LegendItem& i : items) columns = std::max(columns, i.name.size());
    // A stroke two glyphs long and a space before each name.
    return {2.0f * font.pad() + font.advance * float(columns + 3),
            2.0f * font.pad() + font.line_height * float(items.size())};
}

void draw_legend(const std::vector<LegendItem>& items, const render::OverlayFont& font,
                 glm::vec2 at, render::Canvas& canvas) {
    const glm::vec2 size = legend_size(items, font);
    canvas.rects.push_back({at, at + size, kLegendPanel});
    float baseline = at.y + font.pad() + font.ascent;
    const float stroke = std::max(2.0f, 0.22f * font.pixel_height);
    for (const LegendItem& i : items) {
        const float mid = baseline - 0.33f * font.pixel_height;
        const float x0 = at.x + font.pad();
        canvas.strips.push_back({std::uint32_t(canvas.points.size()), 2, i.rgba, stroke});
        canvas.points.push_back({x0, mid});
        canvas.points.push_back({x0 + 2.0f * font.advance, mid});
        canvas.labels.push_back({{x0 + 3.0f * font.advance, baseline}, i.name, kLegendText, -1});
        baseline += font.line_height;
    }
}

} // namespace tumble::app
