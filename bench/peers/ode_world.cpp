#include "bench/peers/ode_world.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace tumble::bench {

using physics::Quat;
using physics::ShapeKind;
using physics::Vec3;

namespace {

constexpr int kMaxPoints = 4; // per pair, as Tumble's manifolds

// Scene body index kept in the geom's data pointer.
void* tag(std::size_t i) {
    return reinterpret_cast<void*>(static_cast<std::uintptr_t>(i));
}
std::size_t index_of(dGeomID g) {
    return static_cast<std::size_t>(reinterpret_cast<std::uintptr_t>(dGeomGetData(g)));
}

dGeomID make_geom(dSpaceID space, const physics::Shape& shape) {
    switch (shape.kind) {
    case ShapeKind::Plane:
        return dCreatePlane(space, 0, 0, 1, 0);
    case ShapeKind::Sphere:
        return dCreateSphere(space, shape.radius);
    case ShapeKind::Box:
        return dCreateBox(space, 2 * shape.half_extents.x(), 2 * shape.half_extents.y(),
                          2 * shape.half_extents.z());
    default:
        throw std::invalid_argument("the ODE peer maps planes, spheres and boxes only");
    }
}

} // namespace

OdeWorld::OdeWorld(const scenes::Scene& scene, OdeSpace space, int iterations)
    : dt_(scene.world.dt), threshold_(scene.world.contact.restitution_threshold) {
    dInitODE2(0);
    world_ = dWorldCreate();
    const Vec3& g = scene.world.gravity;
    dWorldSetGravity(world_, g.x(), g.y(), g.z());
    dWorldSetQuickStepNumIterations(world_, iterations);
    dWorldSetAutoDisableFlag(world_, 0);
    space_ = space == OdeSpace::Hash ? dHashSpaceCreate(nullptr)
                                     : dSweepAndPruneSpaceCreate(nullptr, dSAP_AXES_XYZ);
    joints_ = dJointGroupCreate(0);
    const std::size_t n = scene.bodies.size();
    body_.assign(n, nullptr);
    pose_x_.resize(n);
    pose_q_.resize(n);
    friction_.resize(n);
    restitution_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const physics::BodyDef& b = scene.bodies[i];
        friction_[i] = b.material.friction;
        restitution_[i] = b.material.restitution;
        pose_x_[i] = b.position;
        pose_q_[i] = b.orientation;
        dGeomID geom = make_geom(space_, b.shape);
        dGeomSetData(geom, tag(i));
        const dQuaternion q{b.orientation.w(), b.orientation.x(), b.orientation.y(),
                            b.orientation.z()};
        if (b.motion != physics::Motion::Dynamic) {
            if (b.shape.kind != ShapeKind::Plane) {
                dGeomSetPosition(geom, b.position.x(), b.position.y(), b.position.z());
                dGeomSetQuaternion(geom, q);
            }
            continue;
        }
        dBodyID body = dBodyCreate(world_);
        dMass mass;
        if (b.shape.kind == ShapeKind::Sphere)
            dMassSetSphereTotal(&mass, b.mass, b.shape.radius);
        else
            dMassSetBoxTotal(&mass, b.mass, 2 * b.shape.half_extents.x(),
                             2 * b.shape.half_extents.y(), 2 * b.shape.half_extents.z());
        dBodySetMass(body, &mass);
        dBodySetPosition(body, b.position.x(), b.position.y(), b.position.z());
        dBodySetQuaternion(body, q);
        dBodySetLinearVel(body, b.velocity.x(), b.velocity.y(), b.velocity.z());
        dBodySetAngularVel(body, b.angular_velocity.x(), b.angular_velocity.y(),
                           b.angular_velocity.z());
        dGeomSetBody(geom, body);
        body_[i] = body;
    }
}

OdeWorld::~OdeWorld() {
    dJointGroupDestroy(joints_);
    dSpaceDestroy(space_);
    dWorldDestroy(world_);
    dCloseODE();
}

void OdeWorld::near(void* self, dGeomID a, dGeomID b) {
    OdeWorld& w = *static_cast<OdeWorld*>(self);
    dBodyID ba = dGeomGetBody(a), bb = dGeomGetBody(b);
    if (!ba && !bb) return; // two static geoms
    dContact contact[kMaxPoints];
    const int found = dCollide(a, b, kMaxPoints, &contact[0].geom, sizeof(dContact));
    const std::size_t ia = index_of(a), ib = index_of(b);
    const double mu = std::sqrt(w.friction_[ia] * w.friction_[ib]);
    const double e = std::max(w.restitution_[ia], w.restitution_[ib]);
    for (int k = 0; k < found; ++k) {
        dSurfaceParameters& s = contact[k].surface;
        s.mode = dContactApprox1 | (e > 0 ? dContactBounce : 0);
        s.mu = mu;
        s.bounce = e;
        s.bounce_vel = w.threshold_;
        dJointID j = dJointCreateContact(w.world_, w.joints_, &contact[k]);
        dJointAttach(j, ba, bb);
    }
    w.contacts_ += found;
}

void OdeWorld::step() {
    contacts_ = 0;
    dSpaceCollide(space_, this, &OdeWorld::near);
    dWorldQuickStep(world_, dt_);
    dJointGroupEmpty(joints_);
}

void OdeWorld::fill(physics::State& s) const {
    const std::size_t n = body_.size();
    s.x.resize(n), s.q.resize(n), s.v.resize(n), s.w.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        if (!body_[i]) {
            s.x[i] = pose_x_[i], s.q[i] = pose_q_[i];
            s.v[i] = s.w[i] = Vec3::Zero();
            continue;
        }
        const dReal* x = dBodyGetPosition(body_[i]);
        const dReal* q = dBodyGetQuaternion(body_[i]);
        const dReal* v = dBodyGetLinearVel(body_[i]);
        const dReal* w = dBodyGetAngularVel(body_[i]);
        s.x[i] = Vec3(x[0], x[1], x[2]);
        s.q[i] = Quat(q[0], q[1], q[2], q[3]);
        s.v[i] = Vec3(v[0], v[1], v[2]);
        s.w[i] = Vec3(w[0], w[1], w[2]);
    }
}

} // namespace tumble::bench
