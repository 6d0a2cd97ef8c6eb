#pragma once
// The quantities `tumble plot` draws from a `tumble simulate` run, each with its unit and where it
// comes from; the names are those of `tumble render --chart` where both have one. The definitions
// are physics/diagnostics.h's (the same code computes them):
//   scene totals   the diagnostics table (<stem>.diagnostics.csv): E, T, V, P, L about the world
//                  origin
//   one body       the states table, and for what needs a mass, an inertia or the principal axes
//                  the run's scene (--scene): T_trans = 1/2 m v.v, T_rot = 1/2 w . I_w w with
//                  I_w = R I_body R^T, V = - m s g . x, P = m v, L = I_w w about its centre of
//                  mass, w in the world and w_body = R^T w along the principal axes (the w1, w2, w3
//                  of Euler's equations).
#include "app/run/trajectory_rows.h"
#include "physics/model.h"

#include <string>
#include <string_view>
#include <vector>

namespace tumble::app::plot {

struct Quantity {
    std::string_view name;                    // as --quantity names it
    std::string_view description;             // "total energy", for titles and legends
    std::string_view unit;                    // "J"
    bool of_scene = false;                    // has a scene total in the diagnostics table
    bool of_body = false;                     // has a value per body from the states table
    bool needs_scene = false;                 // per body: needs the scene's masses and inertia
    bool drift = false;                       // drawn as (E(t) - E(0)) / |E(0)|
    std::vector<std::string_view> components; // one series each; empty: one series
};

const std::vector<Quantity>& quantities();
// Null when no quantity has that name.
const Quantity* find_quantity(std::string_view name);
// "energy, kinetic, ..." for messages and --help.
std::string quantity_names();

// The scene total of `q` (of_scene) at one diagnostics row, one value per component.
std::vector<double> scene_values(const Quantity& q, const DiagnosticsRow& row);

// The body's value of `q` (of_body) at one states row. `model` is the run's scene (needed when
// q.needs_scene, else may be null); `row.body` indexes it.
std::vector<double> body_values(const Quantity& q, const physics::Model* model,
                                const StateRow& row);

} // namespace tumble::app::plot
