// midpoint: the implicit midpoint rule on the free rotation, in the state (R, m) with R the 3x3
// orientation and m = I w_b the body momentum, and the loads as half kicks around it (Strang, as
// in `splitting`):
//
//   m' = m + h  m_bar x I^-1 m_bar,      m_bar = (m + m') / 2
//   R' = R + h  R_bar [I^-1 m_bar]x,     R_bar = (R + R') / 2
//
// The second line solves to R' = R cay(h w_bar), w_bar = I^-1 m_bar, with the Cayley transform
// cay(a) = (1 - [a]x / 2)^-1 (1 + [a]x / 2): the rotation about a by 2 atan(|a| / 2), the unit
// quaternion (1, a / 2) / |(1, a / 2)|. The first line likewise reads m' = cay(h w_bar)^T m.
// The 3x3 system F(m_bar) = m_bar - m - h/2 m_bar x I^-1 m_bar = 0 is solved by Newton,
//   J = dF/dm_bar = 1 - h/2 ([m_bar]x I^-1 - [I^-1 m_bar]x),
// from the explicit predictor m + h/2 m x I^-1 m, until the update is below 1e-14 |m| (Newton
// converges quadratically, so the next update would be below round-off): 3 or 4 iterations at
// h |w| <= 1, 5 at h |w| = 4 (measured). After 12 iterations without converging the step fails
// loudly (DivergenceError naming body and step) instead of going on with an unconverged rotation.
// m' is formed as cay(h w_bar)^T m, an exact rotation of m, so R' m' = R m holds to round-off
// whatever the Newton residual.
//
// Order: 2 (symmetric).
// Conserves: every quadratic invariant of the free rigid body, because the implicit midpoint rule
// keeps all quadratic invariants (Cooper 1987): R^T R = 1, |m|^2, the energy m . I^-1 m and the
// world momentum L = R m (bilinear). Energy to the Newton tolerance, L and |m| to round-off.
// The body momentum therefore stays on its exact orbit (energy ellipsoid meets momentum sphere):
// a flip keeps its amplitude.
// Known failure: the error is all phase, O(h^2): the Cayley rotation turns by 2 atan(h |w| / 2),
// less than h |w|, so bodies run slightly late. One 3x3 Newton solve per body and step. Not
// symplectic (on the Lie-Poisson structure the midpoint map is not Poisson), which matters
// only for the statistics of long runs with torques.
#include "physics/compensated.h"
#include "physics/forces.h"
#include "physics/model.h"
#include "physics/rigid_body.h"
#include "physics/state.h"
#include "physics/step.h"

#include <Eigen/LU>

#include <cmath>
#include <string>

namespace tumble::physics {
namespace {

constexpr double kTolerance = 1e-14; // on |dm_bar| / |m|
constexpr int kMaxIterations = 12;

// cay(a) as a unit quaternion: (1, a / 2), normalised.
Quat cayley(const Vec3& a) {
    return Quat(1.0, 0.5 * a.x(), 0.5 * a.y(), 0.5 * a.z()).normalized();
}

// Solves m_bar - m - h/2 m_bar x I^-1 m_bar = 0. Returns false if Newton has not converged.
bool solve_midpoint_momentum(const Vec3& m, const Vec3& inv_I, double h, Vec3& m_bar) {
    const double tol = kTolerance * m.norm();
    m_bar = m + 0.5 * h * m.cross(inv_I.cwiseProduct(m));
    for (int k = 0; k < kMaxIterations; ++k) {
        const Vec3 w_bar = inv_I.cwiseProduct(m_bar);
        const Vec3 F = m_bar - m - 0.5 * h * m_bar.cross(w_bar);
        const Mat3 J =
            Mat3::Identity() - 0.5 * h * (skew(m_bar) * inv_I.asDiagonal() - skew(w_bar));
        const Vec3 dm = J.inverse() * F;
        m_bar -= dm;
        if (dm.norm() <= tol) return true;
    }
    return false;
}

void half_kick(const Model& m, State& s, int i, double h) {
    s.v[i] += 0.5 * h * m.inv_mass[i] * net_force(m, i);
    s.w[i] += angular_velocity_change(m, i, s.q[i], 0.5 * h * net_torque(m, i));
}

} // namespace

void integrate_midpoint(const Model& m, State& s, double h, std::span<const int> bodies) {
    const bool loads = loads_on(m);
    for (int i : bodies) {
        if (loads) half_kick(m, s, i, h);
        add_compensated(s.x[i], s.x_carry[i], h * s.v[i]);
        if (anisotropic(m, i)) {
            const Vec3 mb = m.inertia[i].cwiseProduct(to_body(s.q[i], s.w[i]));
            Vec3 m_bar;
            if (!solve_midpoint_momentum(mb, m.inv_inertia[i], h, m_bar))
                throw DivergenceError(i, s.step + 1, "angular velocity",
                                      "body " + std::to_string(i) +
                                          ": the implicit midpoint solve did not converge in " +
                                          std::to_string(kMaxIterations) + " Newton iterations " +
                                          "in step " + std::to_string(s.step + 1) +
                                          " (try a smaller dt or another integrator)");
            const Quat c = cayley(h * m.inv_inertia[i].cwiseProduct(m_bar));
            s.q[i] = (s.q[i] * c).normalized();
            s.w[i] = rotate(s.q[i], to_body(c, mb).cwiseQuotient(m.inertia[i]));
        } else {
            s.q[i] = (cayley(h * s.w[i]) * s.q[i]).normalized(); // w constant: m_bar = m
        }
        if (loads) half_kick(m, s, i, h);
    }
}

} // namespace tumble::physics
