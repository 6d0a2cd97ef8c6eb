// Contact truths of issue 13 whose expected values are derived here, not read from the model:
// restitution mixed between two unequal materials, and the energy that pushing overlapping bodies
// apart may add. Each at h, 2h and 4h with the measured value printed beside its bound.
#include "physics/diagnostics.h"
#include "physics/scenes/contact_scenes.h"
#include "physics/scenes/scene.h"
#include "scene_sim.h"
#include "support/measured.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace tumble::physics {
namespace {

constexpr double kH = 1.0 / 960.0; // so that 4h is the default 1/240 s
constexpr double kG = 9.81;
const double kSteps[] = {kH, 2 * kH, 4 * kH};

// Restitution between two materials is e = max(e_A, e_B) (docs/contacts.md; Box2D's rule): with
// 0.2 and 0.9 the pair has 0.9 whichever body carries which. A ball dropped from rest with its
// bottom h0 above the plane meets it at V = sqrt(2 g h0), leaves at e V and rises to
//   h1 = (e V)^2 / (2 g) = e^2 h0        (Newton's experimental law of impact)
// = 0.81 m for h0 = 1 m; 0.2 alone would give 0.04 m, the mean 0.55 gives 0.30 m, the geometric
// mean 0.42 gives 0.18 m. The apex is read from the state after the bounce, in free flight:
// z_bottom + vz^2 / (2 g), constant between impacts (the integrator is exact under constant g),
// at the apex time t0 + e V / g (t0 = sqrt(2 h0 / g)), after the first impact and before the
// second. The pair 0.2 and 0.2 checks that 0.9 came from the mixing, not from a default. The
// impact stage leaves with the energy-exact speed (docs/contacts.md: "exactly e^2 times its apex
// whatever the step"), so the bound, 1 mm, is left only for the contact's own slack in the
// impact step (sag, arrival slack 0.1 mm); the other mixing rules miss by 0.5 m or more.
// Measured, the apex is low by 0.03, 0.08, 0.12 mm (e 0.9) and 0.07, 0.17, 0.21 mm (e 0.2) at h,
// 2h, 4h: a small loss in the impact step that grows with h, not quite the documented "exactly".
TEST(IndependentTruths, UnequalRestitutionsMixAsTheLargerForEitherBody) {
    const double h0 = 1.0, r = scenes::kDropBallRadius;
    struct Case {
        double ball, floor, e;
    };
    for (const Case c : {Case{0.9, 0.2, 0.9}, Case{0.2, 0.9, 0.9}, Case{0.2, 0.2, 0.2}}) {
        const double expected = c.e * c.e * h0;
        const double apex_time = std::sqrt(2.0 * h0 / kG) + c.e * std::sqrt(2.0 * kG * h0) / kG;
        for (double dt : kSteps) {
            scenes::Scene s = scenes::ball_drop(c.ball, h0, dt);
            s.bodies[0].material.restitution = c.floor;
            test::Sim run(s);
            run.steps(run.steps_for(apex_time));
            const double vz = run.state.v[1].z();
            const double apex = run.state.x[1].z() - r + vz * vz / (2.0 * kG);
            const double error = std::abs(apex - expected); // m
            std::printf("ball e %.1f, floor e %.1f, dt = 1/%.0f s: apex %.6f m (e^2 h0 = %.6f)\n",
                        c.ball, c.floor, 1.0 / dt, apex, expected);
            TUMBLE_MEASURED(error, 1e-3);
            EXPECT_LT(error, 1e-3);
        }
    }
}

// Two equal bodies of mass m made overlapping by d along x, at rest, no gravity. The soft contact
// pushes the overlap out at the speed min(bias_rate d, max_push_speed), with (docs/contacts.md,
// "Solver", and ContactSettings) the substep h' = h / ceil(1440 h), omega = 2 pi (h'^-1 / 4),
// zeta = 15 and bias_rate = omega / (2 zeta + h' omega): 71.6 /s at h' = 1/1440 s, 95.5 /s at
// 1/1920 s; max_push_speed = 3 m/s. The relax sweeps after each substep's position update solve
// the same points again without that bias: the push moves positions only and never becomes
// velocity. So the exact answer is no kinetic energy at all. The bound: at most 1e-6 of
// E_push = 1/2 (m/2) v_push^2, the energy the pair would keep if the relax sweep were missing
// (m/2 the reduced mass, v_push = min(bias_rate d, 3 m/s) the first substep's push), at every
// step end. Relax skips a point once its gap has opened (sep > 0), which would leave that
// substep's push as velocity; it cannot happen here, since a substep closes only the fraction
// h' bias_rate = 0.05 of the overlap, so the overlap decays geometrically and never overshoots.
struct PushApart {
    double max_kinetic = 0.0; // J, largest at any step end
    double overlap = 0.0;     // m, left at the end
};

PushApart push_apart(bool boxes, double depth, double dt, double seconds) {
    scenes::Scene s;
    s.world.dt = dt;
    s.world.gravity = Vec3::Zero();
    s.world.contact.sleeping = false;
    const double half = 0.1; // half extent of the boxes, radius of the spheres
    for (double side : {-1.0, 1.0}) {
        BodyDef b;
        b.shape = boxes ? Shape::box(Vec3(half, half, half)) : Shape::sphere(half);
        b.mass = 1.0;
        b.position = Vec3(side * (half - 0.5 * depth), 0, 0);
        s.bodies.push_back(b);
    }
    test::Sim run(s);
    PushApart p;
    for (int k = 0; k < run.steps_for(seconds); ++k) {
        run.steps(1);
        p.max_kinetic = std::max(p.max_kinetic, diagnose(run.model, run.state).kinetic());
    }
    p.overlap = 2.0 * half - (run.state.x[1] - run.state.x[0]).norm();
    return p;
}

// Measured KE over E_push for both overlaps at h, 2h and 4h, checked against the bound above.
void expect_no_push_energy(bool boxes, double overlap_left) {
    const ContactSettings settings;
    const double reduced_mass = 0.5;
    for (double depth : {0.005, 0.02})
        for (double dt : kSteps) {
            const double sub = dt / substep_count(settings, dt);
            const double omega = 2.0 * std::numbers::pi * 0.25 / sub;
            const double bias_rate = omega / (2.0 * 15.0 + sub * omega);
            const double v_push = std::min(bias_rate * depth, settings.max_push_speed);
            const double e_push = 0.5 * reduced_mass * v_push * v_push;
            const PushApart p = push_apart(boxes, depth, dt, 2.0);
            const double gained = p.max_kinetic / e_push;
            std::printf("%s overlapping by %.0f mm, dt = 1/%.0f s: kinetic energy at most %.3g J "
                        "(E_push %.3g J), overlap left %.3g m\n",
                        boxes ? "boxes" : "spheres", 1e3 * depth, 1.0 / dt, p.max_kinetic, e_push,
                        p.overlap);
            TUMBLE_MEASURED(gained, 1e-6);
            EXPECT_LT(gained, 1e-6);
            EXPECT_LT(std::abs(p.overlap), overlap_left * depth); // gone, and not much more
        }
}

// Spheres (one contact point): measured 0 J at every step end, the overlap closed to 3e-16 m.
TEST(IndependentTruths, PushingOverlappingSpheresApartAddsNoKineticEnergy) {
    expect_no_push_energy(false, 1e-3);
}

// Boxes (four points, face on face). With one relax sweep per substep the pair flew apart with
// 2.4-3.4% of E_push as kinetic energy: one Gauss-Seidel sweep spread the push unevenly over the
// four points and turned the boxes, and one relax sweep, its impulses clamped at >= 0 per point,
// did not take all of it back. With two (ContactSettings::relax_iterations): measured 3.0e-9 of
// E_push at most (2 cm, 1/960 s), the boxes ending 1.45e-4 m apart after a 2 cm overlap (0.73%;
// 5 mm: 9.6e-6 m, 0.19%): the overlap is gone to within 1% of it. That was fixed effort (2
// substeps of 3 + 2 sweeps at 1/960 s). Effort on demand (issue 28) gives this pair one substep
// of 2 solve and 2 relax sweeps: 4.4e-8 of E_push at most, the boxes ending 3.1e-4 m apart after
// 2 cm (1.6%; 5 mm: 2.1e-5 m, 0.4%): the overlap is gone to within 2% of it.
TEST(IndependentTruths, PushingOverlappingBoxesApartAddsNoKineticEnergy) {
    expect_no_push_energy(true, 2e-2);
}

} // namespace
} // namespace tumble::physics
