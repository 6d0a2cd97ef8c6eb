#include "physics/damper.h"

#include "physics/rigid_body.h"

#include <Eigen/Eigenvalues>

#include <cmath>

namespace tumble::physics {

namespace {

// I_w^-1 of body i as a world matrix (zero for a static body): R I^-1 R^T.
Mat3 world_inverse_inertia(const Model& m, const State& s, int i) {
    if (!m.is_dynamic(i)) return Mat3::Zero();
    const Mat3 r = s.q[i].normalized().toRotationMatrix();
    return r * m.inv_inertia[i].asDiagonal() * r.transpose();
}

} // namespace

void apply_dampers(const Model& m, State& s, double h) {
    for (const Damper& d : m.dampers) {
        // A sleeping body keeps v = w = 0 (the sleep stage): a damper does not stir it.
        if (!s.sleep.asleep.empty() && (s.sleep.asleep[d.a] || s.sleep.asleep[d.b])) continue;
        const Mat3 inv_a = world_inverse_inertia(m, s, d.a),
                   inv_b = world_inverse_inertia(m, s, d.b);
        const Eigen::SelfAdjointEigenSolver<Mat3> k(inv_a + inv_b);
        const Vec3 u0 = s.w[d.b] - s.w[d.a];
        Vec3 f;
        for (int j = 0; j < 3; ++j) {
            const double kj = k.eigenvalues()[j];
            f[j] = -std::expm1(-d.c * h * kj) / kj; // (1 - exp(-c h k)) / k, exact near 0
        }
        const Vec3 impulse = k.eigenvectors() * f.cwiseProduct(k.eigenvectors().transpose() * u0);
        if (m.is_dynamic(d.a)) s.w[d.a] += inv_a * impulse;
        if (m.is_dynamic(d.b)) s.w[d.b] -= inv_b * impulse;
    }
}

} // namespace tumble::physics
