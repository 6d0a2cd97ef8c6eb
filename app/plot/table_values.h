#pragma once
// Where `tumble plot` finds each quantity of the catalogue (app/scene/quantity.h) in the tables
// of a `tumble simulate` run:
//   scene totals   the diagnostics table (<stem>.diagnostics.csv): E, T, V, P, L about the world
//                  origin; it has no columns for T_trans and T_rot
//   one body       the states table, and for what needs a mass, an inertia or the principal axes
//                  the run's scene (--scene), through physics/diagnostics.h as the charts do
// A 3-vector is drawn as its components and, where it means something, its length (|P|).
#include "app/run/trajectory_rows.h"
#include "app/scene/quantity.h"
#include "physics/model.h"

#include <string_view>
#include <vector>

namespace tumble::app::plot {

// The scene total of `q` is a column of the diagnostics table.
bool in_diagnostics_table(Quantity q);
// One body's `q` needs the scene's masses, inertia or principal axes (all but w).
bool needs_scene(Quantity q);
// One name per series drawn: {"Px", "Py", "Pz", "|P|"}; one empty name for a scalar.
std::vector<std::string_view> series_names(Quantity q);

// The scene total of `q` (in_diagnostics_table) at one diagnostics row, one value per series.
std::vector<double> scene_values(Quantity q, const DiagnosticsRow& row);

// The body's value of `q` at one states row, one value per series. `model` is the run's scene
// (needed when needs_scene(q), else may be null); `row.body` indexes it.
std::vector<double> body_values(Quantity q, const physics::Model* model, const StateRow& row);

} // namespace tumble::app::plot
