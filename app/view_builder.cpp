#include "app/view_builder.h"

#include "app/materials.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

namespace tumble::app {
namespace {

// Unit mesh -> body frame scale: unit sphere radius 1, unit box [-1, 1]^3, unit plane 2 x 2.
glm::vec3 mesh_scale(const physics::Shape& s, const BodyLook& look) {
    switch (s.kind) {
    case physics::ShapeKind::Sphere:
        return glm::vec3(static_cast<float>(s.radius));
    case physics::ShapeKind::Box:
        return glm::vec3(s.half_extents.x(), s.half_extents.y(), s.half_extents.z());
    case physics::ShapeKind::Plane:
        return glm::vec3(0.5f * look.plane_extent, 0.5f * look.plane_extent, 1.0f);
    case physics::ShapeKind::Capsule: // physics has them; the scene loader does not make them yet
    case physics::ShapeKind::Mesh:
        break;
    }
    return glm::vec3(1.0f);
}

render::MeshKind mesh_kind(physics::ShapeKind k) {
    switch (k) {
    case physics::ShapeKind::Sphere:
        return render::MeshKind::Sphere;
    case physics::ShapeKind::Box:
        return render::MeshKind::Box;
    case physics::ShapeKind::Plane:
        return render::MeshKind::Plane;
    case physics::ShapeKind::Capsule: // as in mesh_scale()
    case physics::ShapeKind::Mesh:
        break;
    }
    return render::MeshKind::Sphere;
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
    view.instances.clear();
    for (int i = 0; i < model.body_count(); ++i) {
        const physics::Pose pose = physics::body_pose(model, state, i);
        const glm::dquat q(pose.orientation.w(), pose.orientation.x(), pose.orientation.y(),
                           pose.orientation.z());
        glm::mat4 m = glm::mat4(glm::mat4_cast(q)); // rotation, computed in double then rounded
        m[3] = glm::vec4(pose.position.x(), pose.position.y(), pose.position.z(), 1.0);
        m = m * glm::scale(glm::mat4(1.0f), mesh_scale(model.shape[i], scene.looks[i]));
        const physics::ShapeKind kind = model.shape[i].kind;
        render::Instance instance{mesh_kind(kind), m, scene.looks[i].color};
        instance.material = scene.looks[i].material.value_or(default_material(kind));
        instance.axes = scene.render.axes && kind != physics::ShapeKind::Plane;
        view.instances.push_back(instance);
    }
}

} // namespace tumble::app
