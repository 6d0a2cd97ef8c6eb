#pragma once
// A Tumble scene (scenes::Scene) as an ODE 0.16 world, for the peer benchmark (peers_bench.cpp):
// the same bodies, masses, materials, gravity and step, so that both engines run the same scene
// and are judged by the same code (the Tumble State filled from ODE's bodies).
//
// What is mapped, and how:
//   plane (z = 0, normal +z), sphere and box shapes; static bodies as geoms without a body,
//   dynamic ones as bodies with ODE's uniform-density mass of the same total (dMassSet*Total:
//   for spheres and boxes this is Tumble's inertia too);
//   friction mu = sqrt(mu_A mu_B), restitution e = max(e_A, e_B) (Tumble's mixing rules,
//   physics/contact_model.h), with ODE's friction pyramid scaled by the normal force
//   (dContactApprox1, the Coulomb model closest to Tumble's disc) and bounce only above Tumble's
//   restitution threshold (bounce_vel);
//   up to 4 contact points per pair (Tumble's manifolds hold at most 4);
//   quickstep with `iterations` sweeps (ODE's default 20), ERP 0.2 and CFM 1e-5 (ODE's defaults),
//   no auto-disable (the scenes turn sleeping off).
// The collision space is chosen by the caller: ODE's hash space (dHashSpace) or its sweep and
// prune (dSweepAndPruneSpace); the benchmark measures both and reports the faster.
#include "physics/scenes/scene.h"
#include "physics/state.h"

#include <ode/ode.h>

#include <vector>

namespace tumble::bench {

enum class OdeSpace { Hash, SweepAndPrune };

class OdeWorld {
  public:
    OdeWorld(const scenes::Scene& scene, OdeSpace space, int iterations = 20);
    ~OdeWorld();
    OdeWorld(const OdeWorld&) = delete;
    OdeWorld& operator=(const OdeWorld&) = delete;

    void step(); // collide, one dWorldQuickStep of the scene's dt, drop the contact joints
    int contacts() const { return contacts_; } // contact joints made by the last step

    // The state of the scene's bodies as Tumble holds it (x, q, v, w per body; static bodies
    // keep their definition's pose), for the judges of the scenes (scenes::judge_rain, ...).
    void fill(physics::State& state) const;

  private:
    static void near(void* self, dGeomID a, dGeomID b);

    double dt_;
    double threshold_;
    dWorldID world_ = nullptr;
    dSpaceID space_ = nullptr;
    dJointGroupID joints_ = nullptr;
    std::vector<dBodyID> body_;         // per scene body: null for static ones
    std::vector<physics::Vec3> pose_x_; // static bodies' positions
    std::vector<physics::Quat> pose_q_;
    std::vector<double> friction_, restitution_; // per scene body, indexed by geom data
    int contacts_ = 0;
};

} // namespace tumble::bench
