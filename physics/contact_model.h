#pragma once
// What the contact stage reads from the model: materials per body and the world's contact
// settings. Filled for every scene; used only when Model::passes.contacts is on.
#include <algorithm>
#include <cmath>
#include <cstddef>

namespace tumble::physics {

// Per-body surface material. A contact between bodies A and B uses
//   friction    mu = sqrt(mu_A mu_B)    (geometric mean: either surface being frictionless wins)
//   restitution e  = max(e_A, e_B)      (a bouncy ball bounces on any floor)
// (Box2D's default mixing rules, so scenes ported from it behave the same.)
struct Material {
    double friction = 0.5;    // Coulomb coefficient, >= 0
    double restitution = 0.0; // Newton's coefficient, 0 (no bounce) .. 1 (elastic)
};

inline double mix_friction(const Material& a, const Material& b) {
    return std::sqrt(a.friction * b.friction);
}
inline double mix_restitution(const Material& a, const Material& b) {
    return std::max(a.restitution, b.restitution);
}

// The contact tolerance by default, m: the largest sag of a loaded contact and the velocity
// error left in an island (times the step) that effort on demand accepts (contact_effort.cpp).
// Chosen by measurement: the largest that holds every case of the contact stability map at the
// default step (docs/contacts.md, "Effort on demand").
inline constexpr double kDefaultContactTolerance = 1e-4;

struct ContactSettings {
    // Scene switches (docs/scene-format.md, "world").
    bool sleeping = true; // bodies at rest for time_to_sleep stop being simulated
    // Effort. With substeps and iterations both 0 (the default) the effort is on demand: each
    // island of bodies in contact gets the substeps its loads and spin need and is swept until its
    // velocities settle, both following `tolerance` (contact_effort.cpp). A scene that sets either
    // gets exactly that effort in every island, as before issue 28 (fixed_effort below).
    int substeps = 0;   // per step; 0: on demand (fixed: the fewest giving h / n <= 1/kSubstepRate)
    int iterations = 0; // soft solve sweeps per substep (1..64); 0: on demand (fixed: 3)
    double tolerance = kDefaultContactTolerance; // m: the contact tolerance (effort on demand)
    double restitution_threshold = 0.5; // m/s: slower approaches do not bounce (resting stays put)

    // Solver constants (the soft step of Box2D v3, see contact_solver.h).
    // Stiffness of the soft contact, as a frequency: a quarter of the substep rate, the stiffest
    // that stays stable (Box2D v3's cap; 360 Hz at 1440 substeps per second, twice that against a
    // static body). A load F sinks a contact by F / (m_eff (2 pi hertz)^2), so the sag falls with
    // the square of the substep: a 1000 kg cube on a 1 kg one (m_eff about 0.25 kg per corner)
    // sank 21 mm at 480 substeps per second and 2.4 mm at 1440.
    double contact_hertz_fraction = 0.25; // of the substep rate
    // Damping ratio of the soft contact. Higher: the response is more nearly rigid and the spring
    // pushes overlap out more slowly (at bias_rate s, bias_rate = omega / (2 zeta + h omega),
    // 25 per second at 120 Hz), while the sag under a load stays F / (m_eff omega^2) whatever
    // zeta is. Measured (tests/physics/contact_physics_test.cpp, at h, 2h and 4h): with Box2D's
    // 10 a pyramid of 20 boxes keeps jiggling (0.05 rad/s), from 15 on it settles; a tower of 10
    // cubes drifts under 2 mm in 10 s at 15 but up to 13 mm at 25; the 8000-sphere pile keeps
    // every overlap under 1 mm.
    double contact_damping_ratio = 15.0;
    // Relax sweeps per substep (no push-out bias): they take back the push-out velocity. With one,
    // two boxes made to overlap face on face flew apart with 2.4% of the push's kinetic energy
    // (tests/physics/independent_truths_contact_test.cpp); with two, 3e-9 of it.
    int relax_iterations = 2;
    double max_push_speed = 3.0; // m/s: fastest speed at which overlap is pushed out
    // m: contacts this far apart are kept, beyond how far the pair's speeds and loads close the gap
    // in a step (contact_find.cpp, pair_margin): the base covers only the impulses of the step's
    // other contacts. Until 2026-11-28 it was 1 cm (2 cm is Box2D's and Jolt's default for bodies
    // of a metre). At 2 mm the shifted rain of 1000 spheres of 5 cm steps 1.16-1.21x faster, at
    // 8000 1.14x (fewer pairs: fewer constraints to prepare and sweep, smaller islands), its
    // deepest overlap within the tolerance (0.097 and 0.096 mm with the margins' loads term,
    // against 0.098 and 0.091), and every case of the contact stability map measures the same
    // (docs/contacts.md). 1 mm gained another 2%.
    double speculative_distance = 0.002;
    double sleep_speed = 0.05;  // m/s: a body slower than this (at any point) may sleep
    double time_to_sleep = 0.5; // s

    // Scenes with fewer dynamic bodies step on one thread whatever the pool's size (the bits are
    // the same either way). Measured on the project's 2-core VM (bench/sphere_rain_bench.cpp):
    // a step of sphere rain N = 1000 hands out about a hundred jobs of a few microseconds, and
    // two threads ran it at 0.66x of one thread's speed (0.74x with every colour on one thread);
    // from 4096 bodies on the pool is used. Tests set 0 to run the parallel paths on any scene.
    int parallel_min_bodies = 4096;
};

// The policy above: a contact step with this many dynamic bodies runs on the calling thread.
inline bool steps_on_one_thread(const ContactSettings& s, std::size_t dynamic_bodies) {
    return static_cast<long long>(dynamic_bodies) < s.parallel_min_bodies;
}

// Fixed effort: the scene set world.substeps or world.iterations, and every island gets exactly
// that (the other at its fixed default), the same bits as before effort on demand existed.
inline bool fixed_effort(const ContactSettings& s) {
    return s.substeps > 0 || s.iterations > 0;
}

// Fixed effort's automatic substep rate, per second, and its solve sweeps. With 3 sweeps it is the
// least measured that holds every region of the contact stability map at h = 1/240 s
// (docs/contacts.md, "Substeps and sweeps"): at 480 per second and one sweep a stack of 5 boxes
// rocked and walked 6.5 mm in 10 s, and a 1000 kg cube sank 2 cm into the 1 kg cube it stood on.
inline constexpr double kSubstepRate = 1440.0;
inline constexpr int kFixedIterations = 3;

// Fixed effort's substeps of one step h: settings.substeps, or the fewest with h / n <=
// 1 / kSubstepRate.
inline int substep_count(const ContactSettings& s, double h) {
    if (s.substeps > 0) return s.substeps;
    return std::max(1, static_cast<int>(std::ceil(h * kSubstepRate - 1e-9)));
}

// Fixed effort's solve sweeps per substep.
inline int iteration_count(const ContactSettings& s) {
    return s.iterations > 0 ? s.iterations : kFixedIterations;
}

} // namespace tumble::physics
