#pragma once
// What Tumble measures of a run, one catalogue for every command that shows it: the strip charts
// of `tumble render --chart` (and `render.chart` in a scene file) and the figures of
// `tumble plot --quantity`. Each is the scene's sum or one body's share, a scalar or a 3-vector;
// the definitions are physics/diagnostics.h's (the same code computes them):
//   energy        E = T + V                      J
//   energy_drift  (E - E(0)) / |E(0)|            1 (dimensionless)
//   kinetic       T = T_trans + T_rot            J
//   ke_trans      T_trans = 1/2 m v.v            J
//   ke_rot        T_rot = 1/2 w . I_w w          J
//   potential     V = - m s g . x (s: gravity scale) J
//   momentum      P = m v                        kg m/s   (3 components)
//   L             L = I_w w, I_w = R I_body R^T  kg m^2/s (3; a body's spin, the scene's about
//                                                          the origin)
//   w             w, world frame                 rad/s    (3; one body only)
//   w_body        R^T w, the principal frame     rad/s    (3; one body only: the w1, w2, w3 of
//                                                          Euler's equations)
#include "physics/model.h"
#include "physics/state.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace tumble::app {

enum class Quantity : std::uint8_t {
    Energy,
    EnergyDrift,
    Kinetic,
    KineticTranslational,
    KineticRotational,
    Potential,
    Momentum,
    AngularMomentum,
    AngularVelocity,
    AngularVelocityBody,
};
inline constexpr int kQuantityCount = int(Quantity::AngularVelocityBody) + 1;

struct QuantityInfo {
    std::string_view name;        // as --chart, --quantity and render.chart name it
    std::string_view description; // "total energy E = T + V", for titles and axes
    std::string_view unit;        // "J"; "1" when dimensionless
    int components;               // 1 or 3
    std::array<std::string_view, 3> component_names; // "Px", "Py", "Pz" (3-vectors)
    std::string_view norm_name; // "|P|" when its length means something, else ""
    bool of_scene;              // has a scene total (false: one body's only: w, w_body)
    bool drift;                 // relative to its value at t = 0: (x(t) - x(0)) / |x(0)|
};

const QuantityInfo& quantity_info(Quantity q);
std::optional<Quantity> parse_quantity(std::string_view name);
std::string quantity_names(); // "energy, energy_drift, ..." for messages and --help

// The value of `q` now: of body `body`, or of the whole scene when body < 0. `e0` is the same
// energy at t = 0 (for energy_drift). Unused components are 0.
std::array<double, 3> quantity_value(Quantity q, const physics::Model& model,
                                     const physics::State& state, int body, double e0);

// E at this state, of `body` or (body < 0) of the scene: the reference of energy_drift.
double energy_of(const physics::Model& model, const physics::State& state, int body);

} // namespace tumble::app
