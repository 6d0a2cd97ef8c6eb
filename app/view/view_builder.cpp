#include "app/view/view_builder.h"

#include "app/scene/materials.h"
#include "app/view/camera.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

namespace tumble::app {
namespace {

glm::mat4 scaled(const glm::mat4& pose, glm::vec3 scale) {
    return pose * glm::scale(glm::mat4(1.0f), scale);
}

// The body's unit mesh (render/scene_view.h) scaled to its shape: sphere radius 1, box
// [-1, 1]^3, plane 2 x 2, cylinder radius 1 and z in [-1, 1]; a mesh is drawn as given.
render::Instance main_instance(const physics::Shape& s, const BodyLook& look,
                               const glm::mat4& pose) {
    const auto f = [](double x) { return static_cast<float>(x); };
    render::Instance in;
    in.transform = pose;
    switch (s.kind) {
    case physics::ShapeKind::Sphere:
        in.mesh = render::MeshKind::Sphere;
        in.transform = scaled(pose, glm::vec3(f(s.radius)));
        break;
    case physics::ShapeKind::Box:
        in.mesh = render::MeshKind::Box;
        in.transform = scaled(
            pose, glm::vec3(f(s.half_extents.x()), f(s.half_extents.y()), f(s.half_extents.z())));
        break;
    case physics::ShapeKind::Plane:
        in.mesh = render::MeshKind::Plane;
        in.transform =
            scaled(pose, glm::vec3(0.5f * look.plane_extent, 0.5f * look.plane_extent, 1.0f));
        break;
    case physics::ShapeKind::Capsule: // the straight part; capsule_caps() adds the ends
        in.mesh = render::MeshKind::Cylinder;
        in.transform = scaled(pose, glm::vec3(f(s.radius), f(s.radius), f(s.half_length)));
        break;
    case physics::ShapeKind::Mesh:
        in.mesh = render::MeshKind::Custom;
        in.mesh_id = look.mesh_id;
        break;
    }
    return in;
}

// A capsule is drawn as the renderer's cylinder plus a sphere at each end (render/mesh.h): the
// sphere's normals at its equator are the cylinder's, so the seams do not show, and both keep
// their level of detail by size on screen. The caps draw no axes (the cylinder does).
void add_capsule_caps(const physics::Shape& s, const glm::mat4& pose, render::Instance base,
                      std::vector<render::Instance>& out) {
    base.mesh = render::MeshKind::Sphere;
    base.axes = false;
    const float r = static_cast<float>(s.radius), hl = static_cast<float>(s.half_length);
    for (float side : {-1.0f, 1.0f}) {
        const glm::mat4 end = glm::translate(pose, glm::vec3(0.0f, 0.0f, side * hl));
        base.transform = scaled(end, glm::vec3(r));
        out.push_back(base);
    }
}

} // namespace

void build_view(const Scene& scene, const physics::Model& model, const physics::State& state,
                render::SceneView& view) {
    const CameraRig& rig = scene.render.camera;
    glm::dvec3 followed(0.0);
    if (rig.needs_body()) {
        const physics::Vec3 p = physics::body_pose(model, state, rig.follow_body).position;
        followed = {p.x(), p.y(), p.z()};
    }
    view.camera = camera_at(rig, state.time(model), followed);
    view.light = scene.render.light;
    view.background = scene.render.background;
    view.meshes = scene.meshes; // shared pointers: uploaded once by the renderer
    view.instances.clear();
    for (int i = 0; i < model.body_count(); ++i) {
        const physics::Pose pose = physics::body_pose(model, state, i);
        const glm::dquat q(pose.orientation.w(), pose.orientation.x(), pose.orientation.y(),
                           pose.orientation.z());
        glm::mat4 m = glm::mat4(glm::mat4_cast(q)); // rotation, computed in double then rounded
        m[3] = glm::vec4(pose.position.x(), pose.position.y(), pose.position.z(), 1.0);
        const physics::Shape& shape = model.shape[i];
        const BodyLook& look = scene.looks[i];
        render::Instance instance = main_instance(shape, look, m);
        instance.color = look.color;
        instance.material = look.material.value_or(default_material(shape.kind));
        instance.axes = scene.render.axes && shape.kind != physics::ShapeKind::Plane;
        instance.body = i;
        view.instances.push_back(instance);
        if (shape.kind == physics::ShapeKind::Capsule)
            add_capsule_caps(shape, m, instance, view.instances);
    }
}

} // namespace tumble::app
