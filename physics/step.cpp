#include "physics/step.h"

#include "physics/integrators.h"

namespace tumble::physics {

void check_finite(const Model& m, const State& s) {
    for (int i : m.dynamic_bodies) {
        const char* bad = !all_finite(s.x[i])   ? "position"
                          : !all_finite(s.q[i]) ? "orientation"
                          : !all_finite(s.v[i]) ? "velocity"
                          : !all_finite(s.w[i]) ? "angular velocity"
                                                : nullptr;
        if (bad)
            throw DivergenceError(i, s.step, bad,
                                  "body " + std::to_string(i) + ": " + bad +
                                      " is not finite after step " + std::to_string(s.step) +
                                      " (the integrator diverged; try a smaller dt or another "
                                      "integrator)");
    }
}

void step(const Model& m, State& s) {
    const double h = m.dt;
    switch (m.integrator) {
    case Integrator::Euler:
        integrate_euler(m, s, h);
        break;
    case Integrator::EulerMomentum:
        integrate_euler_momentum(m, s, h);
        break;
    case Integrator::SymplecticEuler:
        integrate_symplectic_euler(m, s, h);
        break;
    case Integrator::ImplicitGyro:
        integrate_implicit_gyro(m, s, h);
        break;
    case Integrator::Rk4:
        integrate_rk4(m, s, h);
        break;
    case Integrator::Splitting:
        integrate_splitting(m, s, h);
        break;
    case Integrator::Midpoint:
        integrate_midpoint(m, s, h);
        break;
    case Integrator::Splitting4:
        integrate_splitting4(m, s, h);
        break;
    }
    ++s.step;
    check_finite(m, s);
}

} // namespace tumble::physics
