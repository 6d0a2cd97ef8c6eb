#include "render/draw_list.h"

#include "render/render_error.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace tumble::render {
namespace {

// Batches are drawn in rank order: solid bodies first, the ground last, so that the ground's
// hidden pixels fail the depth test before they are shaded.
int rank_of(MeshKind kind) {
    return kind == MeshKind::Plane ? kGroundRank : 0;
}

// The body-axis rods of an instance: unit cylinders stretched from the body's centre to past its
// surface along each of its axes. Lengths follow the instance's extent along each axis.
struct Rod {
    glm::mat4 transform;
    glm::vec3 color;
};

std::array<Rod, 3> axis_rods(const glm::mat4& t, glm::vec3 unit_half_extent) {
    static const glm::vec3 kColors[3] = {{0.86f, 0.16f, 0.12f}, // x red
                                         {0.20f, 0.70f, 0.22f}, // y green
                                         {0.16f, 0.36f, 0.90f}};
    glm::vec3 extent, axis[3];
    for (int k = 0; k < 3; ++k) {
        const glm::vec3 column(t[k]);
        const float scale = glm::length(column);
        axis[k] = scale > 0.0f ? column / scale : glm::vec3(0.0f);
        extent[k] = scale * unit_half_extent[k];
    }
    const float largest = std::max({extent.x, extent.y, extent.z});
    const float radius = 0.04f * largest;
    std::array<Rod, 3> rods;
    for (int k = 0; k < 3; ++k) {
        const float length = extent[k] + 0.5f * largest; // pokes out of the surface
        // Rod frame: its z along axis k, its x and y along the other two body axes.
        glm::mat4 m(1.0f);
        m[0] = glm::vec4(axis[(k + 1) % 3] * radius, 0.0f);
        m[1] = glm::vec4(axis[(k + 2) % 3] * radius, 0.0f);
        m[2] = glm::vec4(axis[k] * (0.5f * length), 0.0f);
        m[3] = glm::vec4(glm::vec3(t[3]) + axis[k] * (0.5f * length), 1.0f);
        rods[std::size_t(k)] = {m, kColors[k]};
    }
    return rods;
}

float max_scale(const glm::mat4& t) {
    return std::max(
        {glm::length(glm::vec3(t[0])), glm::length(glm::vec3(t[1])), glm::length(glm::vec3(t[2]))});
}

// Radius of the circle a sphere or cylinder instance shows (0 for kinds without levels).
float lod_radius(MeshKind kind, const glm::mat4& t) {
    if (kind == MeshKind::Sphere) return max_scale(t);
    if (kind == MeshKind::Cylinder)
        return std::max(glm::length(glm::vec3(t[0])), glm::length(glm::vec3(t[1])));
    return 0.0f;
}

const GpuMesh& mesh_at_detail(const MeshLibrary& lib, MeshKind kind, float radius_px, float error,
                              float max_edge = 1e9f) {
    if (kind == MeshKind::Sphere)
        return lib.spheres[choose_level(MeshLibrary::kSphereLevels, radius_px, error, max_edge)];
    if (kind == MeshKind::Cylinder)
        return lib
            .cylinders[choose_level(MeshLibrary::kCylinderLevels, radius_px, error, max_edge)];
    return kind == MeshKind::Box ? lib.box : lib.plane;
}

// Everything needed to place one drawable (a body, or one of its axis rods) in both lists.
struct Drawable {
    MeshKind kind;
    const GpuMesh* custom; // for MeshKind::Custom
    glm::mat4 transform;
    glm::vec3 color;
    Material material;
    const std::array<std::int32_t, 2>* occluders = nullptr; // into DrawLists::occluders
};

// Occluders and receivers of ambient occlusion: every body shape that is not a plane. Then each
// receiver's two nearest occluders, and the ground decals under every occluder near a plane.
void find_occluders(const SceneView& view, const std::vector<const GpuMesh*>& custom,
                    const MeshLibrary& lib, DrawLists& out) {
    out.occluders.clear();
    out.receivers.clear();
    out.receiver_of.assign(view.instances.size(), -1);
    for (std::size_t i = 0; i < view.instances.size(); ++i) {
        const Instance& in = view.instances[i];
        if (in.body < 0 || in.mesh == MeshKind::Plane) continue;
        const GpuMesh* unit =
            in.mesh == MeshKind::Custom ? custom[in.mesh_id] : &mesh_at_detail(lib, in.mesh, 0, 1);
        Occluder o = occluder_of(in.mesh, in.transform, unit->half_extent());
        o.body = in.body;
        out.receiver_of[i] = std::int32_t(out.receivers.size());
        out.receivers.push_back({o.centre, unit->radius() * max_scale(in.transform), in.body});
        out.occluders.push_back(o);
    }
    nearest_occluders(out.occluders, out.receivers, out.nearest, out.occluder_order);
    for (const Instance& in : view.instances)
        if (in.mesh == MeshKind::Plane) add_ground_decals(in.transform, out.occluders, out.decals);
}

} // namespace

MeshLibrary::MeshLibrary() {
    for (int segments : kSphereLevels) spheres.emplace_back(make_sphere(segments, segments / 2));
    for (int segments : kCylinderLevels) cylinders.emplace_back(make_cylinder(segments));
    box = GpuMesh(make_box());
    plane = GpuMesh(make_plane());
}

void build_draw_lists(const SceneView& view, const DrawSettings& s, const MeshLibrary& lib,
                      const std::vector<const GpuMesh*>& custom, DrawLists& out) {
    out.camera.clear();
    out.shadow.clear();
    out.caster_bounds.clear();
    out.casters.clear();
    const Camera& cam = view.camera;
    const Frustum frustum = Frustum::from_view_proj(s.view_proj);
    // The part of the view that shadows are drawn in: the camera's frustum cut at
    // shadow_distance. Cut from that frustum, not rebuilt from the camera and an aspect ratio:
    // the aspect this once recovered from the view-projection's diagonal, |vp[1][1] / vp[0][0]|,
    // is the projection's only for a camera looking down -z. vp[0][0] = P[0][0] right.x and
    // vp[1][1] = P[1][1] up.y carry the view's rotation: the default camera (right.x 0.89,
    // up.y 0.17) got 0.35 instead of 16/9, a shadow region a fifth as wide as the picture, and
    // casters towards its sides were culled as if their shadows fell outside it. Their shadows
    // vanished (issue 14: the default scene's blue ball).
    const Frustum shadow_region =
        frustum.cut_at(cam.position, std::min(cam.z_far, s.shadow_distance));
    const glm::vec3 light_dir = glm::normalize(view.light.direction);

    auto place = [&](const Drawable& d) {
        const GpuMesh* unit =
            d.kind == MeshKind::Custom ? d.custom : &mesh_at_detail(lib, d.kind, 0, 1);
        const glm::vec3 centre(d.transform[3]);
        const float bound = unit->radius() * max_scale(d.transform);
        const bool checker = d.kind == MeshKind::Plane;
        const bool closed = d.kind != MeshKind::Plane && d.kind != MeshKind::Custom;
        InstanceData data = make_instance_data(d.transform, d.color, d.material, checker);
        if (d.occluders) {
            for (std::size_t k = 0; k < 2; ++k) {
                const std::int32_t o = (*d.occluders)[k];
                if (o < 0) continue;
                const PackedOccluder rows = pack(out.occluders[std::size_t(o)]);
                for (std::size_t r = 0; r < 3; ++r) data.occluders[3 * k + r] = rows[r];
            }
        }
        const float radius = lod_radius(d.kind, d.transform);
        if (frustum.intersects_sphere(centre, bound)) {
            const float distance = glm::length(centre - cam.position);
            const float px = projected_radius_px(radius, distance, cam.fov_y_deg, s.height);
            const GpuMesh* mesh = d.kind == MeshKind::Custom
                                      ? d.custom
                                      : &mesh_at_detail(lib, d.kind, px, kCameraError, kCameraEdge);
            out.camera.add(mesh, closed, rank_of(d.kind), data, distance);
        }
        if (s.shadows && d.kind != MeshKind::Plane &&
            shadow_region.intersects_swept_sphere(centre, bound, light_dir)) {
            out.caster_bounds.emplace_back(centre, bound);
            out.casters.push_back({data, d.custom, radius, d.kind, closed});
        }
    };

    for (const Instance& inst : view.instances)
        if (inst.mesh == MeshKind::Custom && inst.mesh_id >= custom.size())
            throw RenderError("instance uses custom mesh " + std::to_string(inst.mesh_id) +
                              " but the view has " + std::to_string(custom.size()));
    out.decals.clear();
    if (s.ambient_occlusion) {
        find_occluders(view, custom, lib, out);
        // Only the decals the camera can see (a square of half side h fits in a circle of
        // radius h sqrt(2) < 1.5 h).
        std::erase_if(out.decals, [&frustum](const Decal& d) {
            const float half = glm::length(glm::vec3(d.model[0]));
            return !frustum.intersects_sphere(glm::vec3(d.model[3]), 1.5f * half);
        });
    }
    for (std::size_t i = 0; i < view.instances.size(); ++i) {
        const Instance& inst = view.instances[i];
        const GpuMesh* mesh = inst.mesh == MeshKind::Custom ? custom[inst.mesh_id] : nullptr;
        const std::int32_t receiver = s.ambient_occlusion ? out.receiver_of[i] : -1;
        place({inst.mesh, mesh, inst.transform, inst.color, inst.material,
               receiver >= 0 ? &out.nearest[std::size_t(receiver)] : nullptr});
        if (inst.axes) {
            const glm::vec3 half = mesh ? mesh->half_extent() : glm::vec3(1.0f);
            for (const Rod& rod : axis_rods(inst.transform, half))
                place({MeshKind::Cylinder, nullptr, rod.transform, rod.color, Material{0.4f, 0.4f},
                       nullptr});
        }
    }
    out.camera.finish();
    if (!s.shadows) {
        out.light = {};
        out.shadow.finish();
        return;
    }
    out.light = fit_light_frame(light_dir, out.caster_bounds, s.shadow_map_size);
    for (const PendingCaster& c : out.casters) {
        const float texels = c.lod_radius / out.light.texel_size;
        const GpuMesh* mesh = c.kind == MeshKind::Custom
                                  ? c.custom
                                  : &mesh_at_detail(lib, c.kind, texels, kShadowError);
        out.shadow.add(mesh, c.closed, 0, c.data);
    }
    out.shadow.finish();
}

} // namespace tumble::render
