#pragma once
// What a strip chart can plot (--chart energy,momentum,w; render.chart in a scene file): the
// scene's sums or one body's share,
// each a scalar or a 3-vector plotted as its x, y, z components.
//   energy        E = T + V                      J
//   energy_drift  (E - E(0)) / |E(0)|            (none)
//   ke_trans      T_lin = 1/2 m v.v              J
//   ke_rot        T_rot = 1/2 w . I_w w          J
//   momentum      P = m v                        kg m/s   (3 components)
//   L             L = I_w w, I_w = R I_body R^T  kg m^2/s (3; a body's spin, the scene's about
//                                                          the origin)
//   w             w, world frame                 rad/s    (3; one body)
//   w_body        R^T w, the principal frame     rad/s    (3; one body: the w1, w2, w3 of
//                                                          Euler's equations)
#include "physics/model.h"
#include "physics/state.h"

#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace tumble::app {

enum class ChartQuantity : std::uint8_t {
    Energy,
    EnergyDrift,
    KineticTranslational,
    KineticRotational,
    Momentum,
    AngularMomentum,
    AngularVelocity,
    AngularVelocityBody,
};

struct ChartQuantityInfo {
    const char* name; // as on the command line
    const char* unit; // "" when dimensionless
    int components;   // 1 or 3
    bool needs_body;  // only one body's (w, w_body)
};

const ChartQuantityInfo& chart_quantity_info(ChartQuantity q);
std::optional<ChartQuantity> parse_chart_quantity(std::string_view name);
std::string chart_quantity_names(); // "energy, energy_drift, ..." for messages

// The value of `q` now: of body `body`, or of the whole scene when body < 0. `e0` is the same
// energy at t = 0 (for energy_drift). Unused components are 0.
std::array<double, 3> measure(ChartQuantity q, const physics::Model& model,
                              const physics::State& state, int body, double e0);

// E at this state, of `body` or (body < 0) of the scene: the reference of energy_drift.
double chart_energy(const physics::Model& model, const physics::State& state, int body);

} // namespace tumble::app
