#include "physics/build.h"

#include "physics/build_contacts.h"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <sstream>

namespace tumble::physics {
void require(bool ok, int body, const char* field, const std::string& what) {
    if (!ok) throw ModelError(body, field, what);
}

namespace {

std::string vec_str(const Vec3& v) {
    std::ostringstream s;
    s << "(" << v.x() << ", " << v.y() << ", " << v.z() << ")";
    return s.str();
}

void validate_world(const WorldDef& world) {
    require(world.gravity.allFinite(), -1, "gravity", "gravity must be finite");
    require(std::isfinite(world.dt) && world.dt > 0.0, -1, "dt",
            "time step must be a positive finite number of seconds");
}

void validate_shape(const Shape& s, Motion motion, int body) {
    switch (s.kind) {
    case ShapeKind::Sphere:
        require(std::isfinite(s.radius) && s.radius > 0.0, body, "radius",
                "sphere radius must be positive and finite");
        break;
    case ShapeKind::Box:
        require(s.half_extents.allFinite() && s.half_extents.minCoeff() > 0.0, body, "size",
                "box size must be positive and finite in all three axes");
        break;
    case ShapeKind::Plane:
        require(motion == Motion::Static, body, "static", "a plane is infinite and must be static");
        break;
    case ShapeKind::Capsule:
        require(std::isfinite(s.radius) && s.radius > 0.0, body, "radius",
                "capsule radius must be positive and finite");
        require(std::isfinite(s.half_length) && s.half_length > 0.0, body, "length",
                "capsule length must be positive and finite (a zero-length capsule is a sphere)");
        break;
    case ShapeKind::Mesh:
        break; // validate_mesh_body() checks the triangles
    }
}

// Principal moments must be positive and obey the triangle inequality I1 + I2 >= I3 (and its
// permutations): with I3 = integral of (x^2 + y^2) dm etc., I1 + I2 - I3 = 2 integral z^2 dm >= 0.
// A violation is not a rigid body; the relative slack 1e-12 admits exact flat plates.
void validate_moments(const Vec3& m, int body) {
    require(m.allFinite() && m.minCoeff() > 0.0, body, "inertia",
            "principal moments of inertia must be positive and finite, got " + vec_str(m));
    const double slack = 1e-12 * m.sum();
    for (int k = 0; k < 3; ++k) {
        const double others = m[(k + 1) % 3] + m[(k + 2) % 3];
        require(others + slack >= m[k], body, "inertia",
                "principal moments " + vec_str(m) + " violate the triangle inequality (I" +
                    std::to_string((k + 1) % 3 + 1) + " + I" + std::to_string((k + 2) % 3 + 1) +
                    " < I" + std::to_string(k + 1) + "): no rigid body has this inertia");
    }
}

// Diagonalises a symmetric inertia tensor: returns the principal moments and writes the rotation
// whose columns are the principal axes in body coordinates (a proper rotation, det = +1).
Vec3 principal_axes(const Mat3& tensor, Quat& body_from_mass, int body) {
    require(tensor.allFinite(), body, "inertia", "inertia tensor must be finite");
    require((tensor - tensor.transpose()).cwiseAbs().maxCoeff() <=
                1e-12 * tensor.cwiseAbs().maxCoeff(),
            body, "inertia", "inertia tensor must be symmetric");
    const bool diagonal =
        (tensor - Mat3(tensor.diagonal().asDiagonal())).cwiseAbs().maxCoeff() == 0.0;
    if (diagonal) {
        body_from_mass = Quat::Identity();
        return tensor.diagonal();
    }
    Eigen::SelfAdjointEigenSolver<Mat3> eig(tensor);
    Mat3 axes = eig.eigenvectors();
    if (axes.determinant() < 0.0) axes.col(2) = -axes.col(2);
    body_from_mass = Quat(axes).normalized();
    return eig.eigenvalues();
}

void add_body(Model& m, const BodyDef& b, int i) {
    validate_shape(b.shape, b.motion, i);
    const bool dynamic = b.motion == Motion::Dynamic;
    m.shape.push_back(b.shape);
    m.motion.push_back(b.motion);
    Quat body_from_mass = Quat::Identity();
    Vec3 moments = Vec3::Zero();
    if (dynamic) {
        require(std::isfinite(b.mass) && b.mass > 0.0, i, "mass",
                "mass of a dynamic body must be positive and finite");
        const Mat3 tensor = b.inertia.isZero(0.0) && b.shape.kind == ShapeKind::Mesh
                                ? mesh_inertia(b, i)
                                : b.inertia;
        moments = tensor.isZero(0.0) ? shape_principal_inertia(b.shape, b.mass)
                                     : principal_axes(tensor, body_from_mass, i);
        validate_moments(moments, i);
    }
    require(std::isfinite(b.gravity_scale), i, "gravity_scale", "gravity_scale must be finite");
    require(b.applied_force.allFinite(), i, "force", "applied force must be finite");
    require(b.applied_torque.allFinite(), i, "torque", "applied torque must be finite");
    m.mass.push_back(dynamic ? b.mass : 0.0);
    m.inv_mass.push_back(dynamic ? 1.0 / b.mass : 0.0);
    m.inertia.push_back(moments);
    m.inv_inertia.push_back(dynamic ? Vec3(moments.cwiseInverse()) : Vec3::Zero());
    m.isotropic.push_back(moments.x() == moments.y() && moments.y() == moments.z());
    m.gravity_scale.push_back(b.gravity_scale);
    m.applied_force.push_back(b.applied_force);
    m.applied_torque.push_back(b.applied_torque);
    m.body_from_mass.push_back(body_from_mass);
    // Primitive shapes: centre of mass at the origin; a mesh: its centroid.
    m.com_offset.push_back(b.shape.kind == ShapeKind::Mesh ? mesh_centroid(b, i)
                                                           : Vec3(Vec3::Zero()));
    add_contact_geometry(m, b, i);
    if (dynamic) m.dynamic_bodies.push_back(i);
}

Passes decide_passes(const Model& m) {
    Passes p;
    for (int i : m.dynamic_bodies) {
        p.gravity |= m.gravity_scale[i] != 0.0 && m.gravity != Vec3::Zero();
        p.applied_loads |=
            m.applied_force[i] != Vec3::Zero() || m.applied_torque[i] != Vec3::Zero();
        p.gyroscopic |= !m.isotropic[i];
    }
    p.contacts = m.touch.can_touch; // can_touch.h
    p.dampers = !m.dampers.empty();
    return p;
}

// Each damper couples two different bodies of the scene, at least one of them dynamic, with a
// finite coefficient >= 0.
void add_dampers(Model& m, const std::vector<Damper>& dampers) {
    for (const Damper& d : dampers) {
        const int n = m.body_count();
        require(d.a >= 0 && d.a < n && d.b >= 0 && d.b < n && d.a != d.b, -1, "dampers",
                "a damper couples two different bodies of the scene");
        require(m.is_dynamic(d.a) || m.is_dynamic(d.b), d.a, "dampers",
                "a damper between two static bodies does nothing: one of them must move");
        require(std::isfinite(d.c) && d.c >= 0.0, d.a, "dampers",
                "a damper's coefficient must be finite and >= 0 (N m s)");
        m.dampers.push_back(d);
    }
}

// `exact` follows the torque-free motion (IntegratorInfo::refuses_torque): a body with an applied
// torque has none, and stepping it as if torque-free would be silently wrong. Refused here, naming
// the body and the field.
void check_integrator_fits(const Model& m) {
    const IntegratorInfo& info = integrator_info(m.integrator);
    if (!info.refuses_torque) return;
    // A damper is a torque between two bodies (damper.h).
    if (!m.dampers.empty())
        require(false, m.dampers.front().a, "dampers",
                "the scene has a damper, a torque between two bodies, but the `" +
                    std::string(info.name) +
                    "` integrator steps torque-free bodies only; use `splitting_exact` or "
                    "another integrator");
    for (int i : m.dynamic_bodies)
        require(m.applied_torque[i] == Vec3::Zero(), i, "torque",
                "body " + std::to_string(i) + " has an applied torque " +
                    vec_str(m.applied_torque[i]) + " N m, but the `" + std::string(info.name) +
                    "` integrator steps torque-free bodies only; use "
                    "`splitting_exact` (the exact free flow between half kicks of the torque, "
                    "order 2) or remove the torque");
}

} // namespace

Model build_model(const WorldDef& world, const std::vector<BodyDef>& bodies) {
    validate_world(world);
    Model m;
    m.gravity = world.gravity;
    m.dt = world.dt;
    m.integrator = world.integrator;
    m.contact = world.contact;
    validate_contact_settings(m.contact);
    for (int i = 0; i < static_cast<int>(bodies.size()); ++i) add_body(m, bodies[i], i);
    add_dampers(m, world.dampers);
    m.touch = find_touching_pair(m, bodies);
    m.passes = decide_passes(m);
    check_integrator_fits(m);
    return m;
}

State initial_state(const Model& model, const std::vector<BodyDef>& bodies) {
    State s;
    const int n = model.body_count();
    s.x.resize(n);
    s.q.resize(n);
    s.v.resize(n);
    s.w.resize(n);
    for (int i = 0; i < n; ++i) {
        const BodyDef& b = bodies[i];
        require(b.position.allFinite(), i, "position", "position must be finite");
        require(b.orientation.coeffs().allFinite() && b.orientation.norm() > 0.0, i, "orientation",
                "orientation must be a finite, non-zero quaternion");
        require(b.velocity.allFinite(), i, "velocity", "velocity must be finite");
        require(b.angular_velocity.allFinite(), i, "angular_velocity",
                "angular velocity must be finite");
        const Quat body_q = b.orientation.normalized();
        s.q[i] = (body_q * model.body_from_mass[i]).normalized();
        s.x[i] = b.position + body_q * model.com_offset[i];
        if (!model.is_dynamic(i)) {
            require(b.velocity == Vec3::Zero(), i, "velocity", "a static body cannot move");
            require(b.angular_velocity == Vec3::Zero(), i, "angular_velocity",
                    "a static body cannot rotate");
        }
        s.v[i] = b.velocity;
        s.w[i] = b.angular_velocity;
    }
    s.x_carry.assign(n, Vec3::Zero()); // compensated.h
    // Sized for every model, so that a model whose contacts are forced on (force_all_passes)
    // steps a state built without them.
    s.sleep.asleep.assign(n, 0);
    s.sleep.slow_time.assign(n, 0.0);
    s.sleep.island.assign(n, -1);
    if (model.passes.contacts) check_static_overlaps(model, s);
    return s;
}

} // namespace tumble::physics
