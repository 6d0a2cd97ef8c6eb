// Mass properties and material mixing checked against values derived here, not read back from
// what build_model() made (issue 13: a bug in mass properties would otherwise be shared by the
// code and its oracle).
#include "physics/build.h"
#include "physics/diagnostics.h"
#include "physics/mesh.h"
#include "physics/scenes/contact_scenes.h"
#include "physics/shape.h"
#include "scene_sim.h"
#include "support/measured.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>

namespace tumble::physics {
namespace {

// Closed forms written out in the test: sphere 2/5 m r^2; box of full lengths (x, y, z)
// m/12 (y^2 + z^2) etc.
TEST(IndependentTruths, SphereAndBoxMomentsAreTheTextbookOnes) {
    const double m = 3.0, r = 0.2;
    const Vec3 sphere = shape_principal_inertia(Shape::sphere(r), m);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(sphere[k], 0.4 * m * r * r, 1e-15);
    const double x = 0.6, y = 0.4, z = 0.1; // full lengths; Shape::box takes half extents
    const Vec3 box = shape_principal_inertia(Shape::box(Vec3(x / 2, y / 2, z / 2)), m);
    EXPECT_NEAR(box[0], m / 12 * (y * y + z * z), 1e-15);
    EXPECT_NEAR(box[1], m / 12 * (x * x + z * z), 1e-15);
    EXPECT_NEAR(box[2], m / 12 * (x * x + y * y), 1e-15);
}

// A full, non-diagonal tensor as a user gives it: the model keeps principal moments and the
// rotation to their axes; R diag(I1, I2, I3) R^T must give the tensor back.
TEST(IndependentTruths, ANonDiagonalTensorIsRebuiltFromMomentsAndAxes) {
    Mat3 given;
    given << 2.0, 0.3, -0.1, //
        0.3, 1.5, 0.2,       //
        -0.1, 0.2, 1.8;
    BodyDef b;
    b.shape = Shape::box(Vec3(0.1, 0.1, 0.1));
    b.inertia = given;
    WorldDef world;
    world.gravity = Vec3::Zero();
    const Model model = build_model(world, {b});
    const Mat3 R = model.body_from_mass[0].toRotationMatrix();
    const Mat3 rebuilt = R * model.inertia[0].asDiagonal() * R.transpose();
    const double error = (rebuilt - given).cwiseAbs().maxCoeff();
    TUMBLE_MEASURED(error, 1e-12);
    EXPECT_LT(error, 1e-12);
    EXPECT_NEAR(model.inertia[0].sum(), given.trace(), 1e-12); // the trace is invariant
}

// The world tensor of a turned body, I_w = R I R^T, seen through its spin angular momentum
// L = I_w w: computed here from the tensor given and the orientation, against diagnostics.
TEST(IndependentTruths, TheSpinMomentumOfATurnedBodyIsRIRtW) {
    Mat3 given;
    given << 0.9, -0.2, 0.05, //
        -0.2, 0.8, 0.1,       //
        0.05, 0.1, 0.7;       // positive definite, moments within the triangle inequality
    const Quat q(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));
    const Vec3 w(0.3, -1.2, 2.5);
    BodyDef b;
    b.shape = Shape::box(Vec3(0.2, 0.1, 0.05));
    b.inertia = given;
    b.orientation = q;
    b.angular_velocity = w;
    WorldDef world;
    world.gravity = Vec3::Zero();
    const Model model = build_model(world, {b});
    const State state = initial_state(model, {b});
    const Mat3 R = q.toRotationMatrix();
    const Vec3 expected = R * given * R.transpose() * w;
    const double error = (spin_angular_momentum(model, state, 0) - expected).norm();
    TUMBLE_MEASURED(error, 1e-12);
    EXPECT_LT(error, 1e-12);
}

// Friction between two materials is sqrt(mu_A mu_B): with 0.2 on the ramp and 0.8 on the box the
// pair has 0.4. At 25 degrees (tan 0.466 > 0.4) the box slides at g (sin - 0.4 cos); at 20
// degrees (tan 0.364 < 0.4) it stays. Neither material alone would give both.
TEST(IndependentTruths, UnequalFrictionsMixAsTheGeometricMean) {
    const double g = 9.81, mu = std::sqrt(0.2 * 0.8);
    auto slide = [&](double degrees) {
        const double angle = degrees * std::numbers::pi / 180.0;
        scenes::Scene s = scenes::incline(angle, 0.2, 1.0 / 240.0, false);
        s.bodies[1].material.friction = 0.8;
        test::Sim run(s);
        run.steps(run.steps_for(1.0));
        const Vec3 downhill = Quat(Eigen::AngleAxisd(angle, Vec3::UnitY())) * Vec3(1, 0, 0);
        return run.state.v[1].dot(downhill) / run.state.time(run.model);
    };
    const double a25 = slide(25.0), a20 = slide(20.0);
    const double expected = g * (std::sin(25.0 * std::numbers::pi / 180.0) -
                                 mu * std::cos(25.0 * std::numbers::pi / 180.0));
    const double err = std::abs(a25 / expected - 1.0);
    TUMBLE_MEASURED(err, 0.02);
    EXPECT_LT(err, 0.02);
    TUMBLE_MEASURED(std::abs(a20), 1e-3);
    EXPECT_LT(std::abs(a20), 1e-3);
}

// A box slid along flat ground at v0 with friction mu stops after t = v0 / (mu g), having gone
// d = v0^2 / (2 mu g) (constant deceleration mu g), at h, 2h and 4h (h = 1/960 s). Measured
// distance errors 0.085%, 0.11%, 0.11%, the stop 0.88 ms late at each: the solver substeps to at
// most 1/1440 s, so 2h and 4h agree.
TEST(IndependentTruths, ASlidingBoxStopsOverTheClosedFormDistance) {
    const double g = 9.81, mu = 0.5, v0 = 3.0;
    const double distance = v0 * v0 / (2.0 * mu * g), stop = v0 / (mu * g);
    // Stopped: slower than 0.1 mm/s (friction takes that in 20 us). Once stopped the box keeps a
    // residual rock of about 1e-6 m/s for a few steps, as the load settles on its four corners.
    constexpr double kStopped = 1e-4;
    for (double dt : {1.0 / 960.0, 1.0 / 480.0, 1.0 / 240.0}) {
        scenes::Scene s = scenes::incline(0.0, mu, dt, false); // a level "ramp"
        s.bodies[1].velocity = Vec3(v0, 0, 0);
        test::Sim run(s);
        const double x0 = run.state.x[1].x();
        double stopped_at = -1.0;
        for (int k = 0; k < run.steps_for(2.0 * stop); ++k) {
            run.steps(1);
            if (stopped_at < 0.0 && run.state.v[1].x() <= kStopped) stopped_at = (k + 1) * dt;
        }
        const double slid = run.state.x[1].x() - x0;
        const double distance_error = std::abs(slid / distance - 1.0);
        const double time_error = std::abs(stopped_at - stop);
        std::printf("dt = 1/%.0f s: slid %.6f m (closed form %.6f), stopped at %.5f s (%.5f)\n",
                    1.0 / dt, slid, distance, stopped_at, stop);
        TUMBLE_MEASURED(distance_error, 0.01);
        EXPECT_LT(distance_error, 0.01);
        TUMBLE_MEASURED(time_error, 2 * dt);
        EXPECT_LT(time_error, 2 * dt); // the stop is read to the step
    }
}

// A box on a ramp slides exactly when tan(angle) > mu: half a degree either side of
// atan(0.5) = 26.565 degrees it holds, or slides at g (sin - mu cos), at h, 2h and 4h. Measured:
// holds to 4e-16 m/s^2; slides within 0.16%, 0.22%, 0.22% of the closed form (a small difference
// of two large terms, so a relative error a few times that of the 30-degree test).
TEST(IndependentTruths, ABoxSlidesExactlyWhenTheSlopeExceedsTheFrictionAngle) {
    const double g = 9.81, mu = 0.5, critical = std::atan(mu) * 180.0 / std::numbers::pi;
    for (double dt : {1.0 / 960.0, 1.0 / 480.0, 1.0 / 240.0}) {
        auto accel = [&](double degrees) {
            const double angle = degrees * std::numbers::pi / 180.0;
            test::Sim run(scenes::incline(angle, mu, dt, false));
            run.steps(run.steps_for(1.0));
            const Vec3 downhill = Quat(Eigen::AngleAxisd(angle, Vec3::UnitY())) * Vec3(1, 0, 0);
            return run.state.v[1].dot(downhill) / run.state.time(run.model);
        };
        const double below = accel(critical - 0.5), above = accel(critical + 0.5);
        const double a = (critical + 0.5) * std::numbers::pi / 180.0;
        const double expected = g * (std::sin(a) - mu * std::cos(a)); // 0.0957 m/s^2
        const double slide_error = std::abs(above / expected - 1.0);
        std::printf("dt = 1/%.0f s: below %.3g m/s^2, above %.6f (closed form %.6f)\n", 1.0 / dt,
                    below, above, expected);
        TUMBLE_MEASURED(std::abs(below), 1e-6);
        EXPECT_LT(std::abs(below), 1e-6);
        TUMBLE_MEASURED(slide_error, 0.05);
        EXPECT_LT(slide_error, 0.05);
    }
}

// Gauss-Legendre with 3 points on [a, b]: exact for polynomials of degree <= 5.
template <class F>
double gauss3(F f, double a, double b) {
    const double mid = 0.5 * (a + b), half = 0.5 * (b - a), x = std::sqrt(0.6);
    return half * (5.0 * f(mid - half * x) + 8.0 * f(mid) + 5.0 * f(mid + half * x)) / 9.0;
}

// Capsule of radius r, cylinder length L (Shape::capsule takes L / 2), axis z, mass m. Textbook
// closed form (e.g. the tables of Meriam and Kraige, Engineering Mechanics: Dynamics, appendix B):
// split the mass into the cylinder, m_c, and two hemispheres, m_h each, in proportion to their
// volumes pi r^2 L and 2/3 pi r^3.
//   Axis:       cylinder 1/2 m_c r^2; a hemisphere is half a ball, so 2/5 m_h r^2.
//   Transverse: cylinder m_c (L^2/12 + r^2/4). A hemisphere about a diameter of its flat face has
//               2/5 m_h r^2 (half the ball's); its centroid is 3r/8 from that face (int z dV over
//               the half ball = pi r^4/4, over its volume 2/3 pi r^3), so about its centroid
//               2/5 r^2 - (3r/8)^2 = 83/320 r^2, and about the capsule's centre, L/2 + 3r/8 away,
//               m_h (83/320 r^2 + (L/2 + 3r/8)^2).
// The same moments from slices, independently of that algebra: the radius of the disc at height
// z is R(z)^2 = r^2 on the cylinder and r^2 - (|z| - L/2)^2 on the caps, and a disc of mass dm
// has dm R^2/2 about the axis and dm (R^2/4 + z^2) about a transverse axis through the centre
// (Gauss-Legendre, exact here: the integrands are polynomials of degree 4 on each piece).
TEST(IndependentTruths, CapsuleMomentsAreCylinderPlusShiftedHemispheres) {
    const double m = 2.0, r = 0.1, L = 0.5, pi = std::numbers::pi;
    const double v_cyl = pi * r * r * L, v_hemi = 2.0 / 3.0 * pi * r * r * r;
    const double volume = v_cyl + 2.0 * v_hemi;
    const double m_c = m * v_cyl / volume, m_h = m * v_hemi / volume;
    const double axis = 0.5 * m_c * r * r + 2.0 * (0.4 * m_h * r * r);
    const double shift = 0.5 * L + 3.0 * r / 8.0;
    const double across =
        m_c * (L * L / 12.0 + r * r / 4.0) + 2.0 * m_h * (83.0 / 320.0 * r * r + shift * shift);

    const double rho = m / volume;
    auto r2 = [&](double z) {
        const double out = std::max(0.0, std::abs(z) - 0.5 * L);
        return r * r - out * out;
    };
    double slice_axis = 0.0, slice_across = 0.0;
    const double pieces[][2] = {
        {-0.5 * L - r, -0.5 * L}, {-0.5 * L, 0.5 * L}, {0.5 * L, 0.5 * L + r}};
    for (const auto& [a, b] : pieces) {
        slice_axis += gauss3([&](double z) { return rho * pi * r2(z) * r2(z) / 2.0; }, a, b);
        slice_across +=
            gauss3([&](double z) { return rho * pi * r2(z) * (r2(z) / 4.0 + z * z); }, a, b);
    }
    const double closed_vs_slices =
        std::max(std::abs(axis / slice_axis - 1.0), std::abs(across / slice_across - 1.0));
    EXPECT_LT(closed_vs_slices, 1e-13);

    const Shape capsule = Shape::capsule(r, 0.5 * L);
    const Vec3 code = shape_principal_inertia(capsule, m);
    const double error =
        std::max({std::abs(code[0] / across - 1.0), std::abs(code[1] / across - 1.0),
                  std::abs(code[2] / axis - 1.0)});
    std::printf("capsule: I1 = I2 = %.10g, I3 = %.10g kg m^2 (closed form %.10g, %.10g)\n", code[0],
                code[2], across, axis);
    TUMBLE_MEASURED(error, 1e-12);
    EXPECT_LT(error, 1e-12);
    const double volume_error = std::abs(shape_volume(capsule) / volume - 1.0);
    TUMBLE_MEASURED(volume_error, 1e-14);
    EXPECT_LT(volume_error, 1e-14);
}

// A cuboid of full lengths `size` as a closed mesh of 12 triangles, corners turned by `turn` and
// then moved by `centre` (body frame). Corner k = (bit 0, bit 1, bit 2) -> (x, y, z) high or low;
// each face is listed counter-clockwise seen from outside, split along a diagonal.
std::shared_ptr<TriangleMesh> cuboid_mesh(const Vec3& size, const Quat& turn, const Vec3& centre) {
    auto mesh = std::make_shared<TriangleMesh>();
    for (int k = 0; k < 8; ++k) {
        const Vec3 unit((k & 1) ? 0.5 : -0.5, (k & 2) ? 0.5 : -0.5, (k & 4) ? 0.5 : -0.5);
        mesh->vertices.push_back(centre + turn * Vec3(unit.cwiseProduct(size)));
    }
    const std::array<int, 4> faces[] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                        {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    for (const auto& f : faces) {
        mesh->triangles.push_back({f[0], f[1], f[2]});
        mesh->triangles.push_back({f[0], f[2], f[3]});
    }
    return mesh;
}

// A mesh cube of edge a and density rho: m = rho a^3, centre at its middle, and the cube's
// moments m a^2 / 6 about any axis through it (the box's m/12 (a^2 + a^2)), both from the exact
// polyhedral integrals at unit density and through build_model() with the mass m given.
TEST(IndependentTruths, AMeshCubeHasTheCubesMassCentreAndMoments) {
    const double a = 0.3, rho = 700.0, m = rho * a * a * a, moment = m * a * a / 6.0;
    const auto cube = cuboid_mesh(Vec3(a, a, a), Quat::Identity(), Vec3::Zero());
    ASSERT_FALSE(check_closed_mesh(*cube).has_value());
    const MeshMassProperties unit = mesh_mass_properties(*cube);
    const double mass_error = std::abs(rho * unit.volume / m - 1.0);
    const double tensor_error =
        (rho * unit.inertia - moment * Mat3::Identity()).cwiseAbs().maxCoeff() / moment;
    TUMBLE_MEASURED(mass_error, 1e-14);
    EXPECT_LT(mass_error, 1e-14);
    TUMBLE_MEASURED(tensor_error, 1e-13);
    EXPECT_LT(tensor_error, 1e-13);
    EXPECT_LT(unit.centroid.norm(), 1e-15);

    BodyDef b;
    b.shape = Shape::mesh();
    b.mesh = cube;
    b.mass = m;
    WorldDef world;
    world.gravity = Vec3::Zero();
    const Model model = build_model(world, {b});
    const double model_error = (model.inertia[0] / moment - Vec3::Ones()).cwiseAbs().maxCoeff();
    TUMBLE_MEASURED(model_error, 1e-13);
    EXPECT_LT(model_error, 1e-13);
    EXPECT_LT(model.com_offset[0].norm(), 1e-15);
}

// Off centre and turned: a 0.4 x 0.2 x 0.1 m cuboid mesh whose corners are turned by R and moved
// to c in its body frame. Its centre of mass is c, and its tensor about c is R diag(m/12 (y^2 +
// z^2), m/12 (x^2 + z^2), m/12 (x^2 + y^2)) R^T (the box's, turned). The model must keep c as the
// centre (com_offset), rebuild the tensor from its moments and axes, and the initial state must
// put the centre of mass at position + orientation c.
TEST(IndependentTruths, AnOffCentreTurnedMeshBoxKeepsItsCentreAndTensor) {
    const double x = 0.4, y = 0.2, z = 0.1, m = 5.0;
    const Vec3 c(0.5, -0.2, 0.8);
    const Quat R(Eigen::AngleAxisd(0.6, Vec3(1, -2, 0.5).normalized()));
    const Mat3 expected =
        R.toRotationMatrix() *
        Vec3(m / 12 * (y * y + z * z), m / 12 * (x * x + z * z), m / 12 * (x * x + y * y))
            .asDiagonal() *
        R.toRotationMatrix().transpose();
    BodyDef b;
    b.shape = Shape::mesh();
    b.mesh = cuboid_mesh(Vec3(x, y, z), R, c);
    b.mass = m;
    b.position = Vec3(1.0, 2.0, 3.0);
    b.orientation = Quat(Eigen::AngleAxisd(0.3, Vec3::UnitZ()));
    ASSERT_FALSE(check_closed_mesh(*b.mesh).has_value());
    WorldDef world;
    world.gravity = Vec3::Zero();
    const Model model = build_model(world, {b});
    const State state = initial_state(model, {b});
    const Mat3 axes = model.body_from_mass[0].toRotationMatrix();
    const Mat3 rebuilt = axes * model.inertia[0].asDiagonal() * axes.transpose();
    const double tensor_error = (rebuilt - expected).cwiseAbs().maxCoeff() / expected.maxCoeff();
    const double centre_error = (model.com_offset[0] - c).norm();
    const double state_error = (state.x[0] - (b.position + b.orientation * c)).norm();
    TUMBLE_MEASURED(tensor_error, 1e-12);
    EXPECT_LT(tensor_error, 1e-12);
    TUMBLE_MEASURED(centre_error, 1e-14);
    EXPECT_LT(centre_error, 1e-14);
    TUMBLE_MEASURED(state_error, 1e-14);
    EXPECT_LT(state_error, 1e-14);
}

} // namespace
} // namespace tumble::physics
