// A heavy fast top precesses at Omega = m g d / (I3 w3) (issue 13): a convex mesh top with a
// point tip on a plane with friction 1, its mass properties computed here by slices, not read
// from the model, at h, 2h and 4h with the measured error printed beside each bound.
//
// Heavy symmetric top with a fixed tip (Goldstein, Classical Mechanics, 3rd ed., section 5.7;
// Landau and Lifshitz, Mechanics, section 35). With the tilt theta of the axis from the vertical,
// the precession rate phi' = Omega about the vertical, the spin component w3 = psi' + Omega cos
// theta along the axis, I1' the transverse moment about the tip and d the tip-to-centre distance,
//   L = I1'/2 (theta'^2 + phi'^2 sin^2 theta) + I3/2 w3^2 - m g d cos theta,
// and the theta equation with theta' = theta'' = 0 (steady precession) is
//   I1' cos(theta) Omega^2 - I3 w3 Omega + m g d = 0,
// whose slow root is
//   Omega = (I3 w3 - sqrt(I3^2 w3^2 - 4 I1' cos(theta) m g d)) / (2 I1' cos theta)
//         = m g d / (I3 w3) (1 + eps + O(eps^2)),   eps = I1' cos(theta) m g d / (I3 w3)^2,
// the fast-top rate when the spin dominates (eps << 1). Started on that steady motion (angular
// velocity Omega e_z + (w3 - Omega cos theta) a, centre velocity Omega e_z x d a) the top has no
// nutation, and its axis turns about the vertical at the exact root.
#include "physics/build.h"
#include "physics/mesh.h"
#include "physics/scenes/ground.h"
#include "physics/scenes/scene.h"
#include "scene_sim.h"
#include "support/measured.h"

#include "physics/scenes/stability_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>

namespace tumble::physics {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kSides = 48;
// Profile of the solid of revolution, (radius, height) in m: a point tip at the origin, a cone
// out to a 4 cm rim at 3 cm, the rim up to 3.6 cm, a crown narrowing to 8 mm at 5.6 cm.
constexpr double kProfile[][2] = {{0.0, 0.0}, {0.040, 0.030}, {0.040, 0.036}, {0.008, 0.056}};
constexpr int kRings = 3; // the profile's points after the tip

// The mesh is scenes::sharp_top_mesh(kSides), the contact map's top, whose profile kProfile
// repeats; its mass properties below are computed here by slices, not by mesh_mass.cpp.
struct TopMass {
    double m, d, i1_tip, i1, i3; // kg, m (tip to centre), kg m^2
};

// Mass properties by slices, independently of the polyhedral integrals of mesh_mass.cpp. Each side
// face is a planar trapezoid (its two horizontal edges are parallel), so the section at height z
// is the regular n-gon of circumradius R(z), linear in z on each piece of the profile. The n-gon
// is n triangles (0, P, Q) with |P| = |Q| = R and angle t = 2 pi / n between them, each of area
// 1/2 R^2 sin t and polar moment (area / 6)(P.P + Q.Q + P.Q) = R^4 sin t (2 + cos t) / 12, so
//   A(z) = n/2 sin(t) R^2,   J(z) = n sin(t) (2 + cos t) R^4 / 12   (pi R^2, pi R^4 / 2 as n grows)
// and, the n-gon being symmetric under a turn by t, its moments about x and y are J / 2 each. Then
//   m = rho int A dz,  m d = rho int A z dz,  I3 = rho int J dz,  I1' = rho int (J/2 + A z^2) dz,
// with polynomials of degree <= 4 on each piece: 3-point Gauss-Legendre is exact.
TopMass top_mass(double density) {
    const double t = 2.0 * kPi / kSides;
    const double area = 0.5 * kSides * std::sin(t),
                 polar = kSides * std::sin(t) * (2 + std::cos(t)) / 12;
    const double node = std::sqrt(0.6), weight[] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
    double v = 0.0, vz = 0.0, i3 = 0.0, i1 = 0.0;
    for (int p = 0; p < kRings; ++p) {
        const double r0 = kProfile[p][0], z0 = kProfile[p][1];
        const double r1 = kProfile[p + 1][0], z1 = kProfile[p + 1][1];
        for (int k = 0; k < 3; ++k) {
            const double s = 0.5 * (1.0 + (k - 1) * node); // 0..1 along the piece
            const double z = z0 + s * (z1 - z0), r = r0 + s * (r1 - r0);
            const double w = 0.5 * weight[k] * (z1 - z0);
            const double a = area * r * r, j = polar * r * r * r * r;
            v += w * a, vz += w * a * z, i3 += w * j, i1 += w * (0.5 * j + a * z * z);
        }
    }
    TopMass top;
    top.m = density * v;
    top.d = vz / v;
    top.i3 = density * i3;
    top.i1_tip = density * i1;
    top.i1 = top.i1_tip - top.m * top.d * top.d; // parallel axes, back to the centre
    return top;
}

constexpr double kG = 9.81, kDensity = 1200.0;
constexpr double kTilt = 20.0 * kPi / 180.0, kSpin = 500.0; // rad, rad/s (w3)

double exact_rate(const TopMass& top) {
    const double c = top.i1_tip * std::cos(kTilt), l = top.i3 * kSpin;
    return (l - std::sqrt(l * l - 4.0 * c * top.m * kG * top.d)) / (2.0 * c);
}

// The model's mass properties agree with the slices (a second, independent check of the mesh
// integrals on a body that is not a box).
TEST(TopPrecession, TheMeshTopsMassPropertiesMatchTheSlices) {
    const TopMass top = top_mass(kDensity);
    BodyDef b;
    b.shape = Shape::mesh();
    b.mesh = scenes::sharp_top_mesh(kSides);
    b.mass = top.m;
    ASSERT_FALSE(check_closed_mesh(*b.mesh).has_value());
    WorldDef world;
    const Model model = build_model(world, {b});
    const double volume_error =
        std::abs(kDensity * mesh_mass_properties(*b.mesh).volume / top.m - 1);
    const Vec3 moments = model.inertia[0];
    const double i1 = std::min(moments.x(), moments.y()), i2 = std::max(moments.x(), moments.y());
    const double error = std::max({volume_error, std::abs(i1 / top.i1 - 1),
                                   std::abs(i2 / top.i1 - 1), std::abs(moments.z() / top.i3 - 1),
                                   (model.com_offset[0] - Vec3(0, 0, top.d)).norm() / top.d});
    std::printf("m = %.6g kg, d = %.6g m, I1 = %.6g, I3 = %.6g kg m^2\n", top.m, top.d, top.i1,
                top.i3);
    TUMBLE_MEASURED(error, 1e-12);
    EXPECT_LT(error, 1e-12);
}

struct Precession {
    double rate;       // rad/s, least-squares slope of the unwrapped azimuth of the axis
    double tilt_drift; // rad, largest |theta - theta0|
    double tip_slide;  // m, largest horizontal distance of the tip from where it started
    double spin_end;   // rad/s, w3 at the end
};

Precession spin_top(const TopMass& top, double dt, double seconds) {
    const double omega = exact_rate(top);
    scenes::Scene s;
    s.world.dt = dt;
    s.world.contact.sleeping = false;
    BodyDef b;
    b.shape = Shape::mesh();
    b.mesh = scenes::sharp_top_mesh(kSides);
    b.mass = top.m;
    b.material.friction = 1.0;
    b.orientation = Quat(Eigen::AngleAxisd(kTilt, Vec3::UnitX()));
    const Vec3 axis = b.orientation * Vec3::UnitZ(); // (0, -sin, cos)
    b.position = Vec3::Zero();                       // the tip on the plane
    b.angular_velocity = omega * Vec3::UnitZ() + (kSpin - omega * std::cos(kTilt)) * axis;
    b.velocity = omega * top.d * Vec3::UnitZ().cross(axis);
    s.bodies = {scenes::ground(1.0), b};
    test::Sim run(s);

    // Unwrapped azimuth of the axis, fitted by least squares against time.
    double last = std::atan2(axis.y(), axis.x()), turned = 0.0;
    double st = 0, sp = 0, stt = 0, stp = 0;
    Precession p{0.0, 0.0, 0.0, 0.0};
    const int n = run.steps_for(seconds);
    for (int k = 0; k <= n; ++k) {
        if (k > 0) run.steps(1);
        const Pose pose = body_pose(run.model, run.state, 1);
        const Vec3 a = pose.orientation * Vec3::UnitZ();
        const double azimuth = std::atan2(a.y(), a.x());
        turned += std::remainder(azimuth - last, 2.0 * kPi);
        last = azimuth;
        const double t = k * dt;
        st += t, sp += turned, stt += t * t, stp += t * turned;
        p.tilt_drift = std::max(p.tilt_drift, std::abs(std::acos(a.z()) - kTilt));
        p.tip_slide = std::max(p.tip_slide, pose.position.head<2>().norm());
        p.spin_end = run.state.w[1].dot(a);
    }
    const double count = n + 1;
    p.rate = (count * stp - st * sp) / (count * stt - st * st);
    return p;
}

// At w3 = 500 rad/s and 20 degrees the top (m = 0.146 kg, d = 3.18 cm, I1' = 2.02e-4, I3 =
// 8.16e-5 kg m^2) precesses at 1.116 rad/s by the fast-top formula and 1.122 rad/s by the exact
// root (eps = 0.5%); Omega / w3 = 2.2e-3. The rate is fitted over one precession period (5.6 s)
// and held within 2% of the fast-top formula (the bound) and within 1% of the exact root,
// at h, 2h and 4h with h = 1/960 s (4h the default 1/240 s; the contact substep is at most
// 1/1440 s). Measured: 0.53%, 0.53%, 0.52% from the fast-top formula; 0.0065%, 0.0083%, 0.0039%
// from the exact root. With friction 1 the tip should not slide (the centre's circle needs
// m Omega^2 d sin(theta) = 2 mN of the 1.4 N available), yet it walks 3.9, 5.0 and 4.6 mm from
// where it stood, while w3 falls to 499.99, 499.97 and 499.97 rad/s: printed below, not asserted.
// (Before issue 13's turning anchors the tip walked up to 3.3 cm and w3 rose to 500.46 rad/s,
// +19 mJ; the figures were 0.56-0.67% and 0.035-0.14%.)
TEST(TopPrecession, AHeavyFastTopPrecessesAtMgdOverI3W3) {
    const TopMass top = top_mass(kDensity);
    const double fast = top.m * kG * top.d / (top.i3 * kSpin), exact = exact_rate(top);
    std::printf("fast top %.6f rad/s, exact steady root %.6f rad/s (Omega / w3 = %.2g)\n", fast,
                exact, fast / kSpin);
    for (double dt : {1.0 / 960.0, 1.0 / 480.0, 1.0 / 240.0}) {
        const Precession p = spin_top(top, dt, 2.0 * kPi / fast);
        const double fast_error = std::abs(p.rate / fast - 1.0);
        const double exact_error = std::abs(p.rate / exact - 1.0);
        std::printf("dt = 1/%.0f s: precession %.6f rad/s, tilt drift %.3g rad, tip slide %.3g m, "
                    "w3 %.3f rad/s at the end\n",
                    1.0 / dt, p.rate, p.tilt_drift, p.tip_slide, p.spin_end);
        TUMBLE_MEASURED(fast_error, 0.02);
        EXPECT_LT(fast_error, 0.02);
        TUMBLE_MEASURED(exact_error, 0.01);
        EXPECT_LT(exact_error, 0.01);
    }
}

} // namespace
} // namespace tumble::physics
