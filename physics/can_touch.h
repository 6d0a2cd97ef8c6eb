#pragma once
// "Can two shapes touch?": the decision that turns the contact stage on (Passes::contacts), made
// once by build_model() from the initial state in the body definitions.
//
// Until the first contact every dynamic body moves under its loads alone, so its centre of mass
// follows x(t) = x0 + v0 t + 1/2 a t^2 with the constant a = g s + F_applied / m (forces.h), and
// every point of its shape stays within its bounding radius R (bounding_radius() below) of that
// centre. For a pair (A, B) with at least one dynamic body, the relative centre
//   p(t) = d + u t + 1/2 a t^2,   d = xB - xA, u = vB - vA, a = aB - aA
// decides:
//   a != 0        can touch (conservative: the pair accelerates towards or past each other)
//   a == 0        free relative flight, closest approach at t* = max(0, -d.u / |u|^2):
//                 can touch iff |p(t*)| <= RA + RB + margin
//   plane P, a = 0: the body's signed distance z(t) = z0 + (n.u) t to the plane; can touch iff
//                 n.u < 0 (it approaches, and the plane is infinite) or z0 <= R + margin
// where margin = 2 speculative_distance + dt (|u| + spin), spin = |wA|max swingA + |wB|max swingB
// covers the contact stage's speculative margin (contact_find.cpp), so a scene decided "cannot
// touch" would never have had a contact point either: turning contacts off changes no bit.
// |w| of a torque-free body is bounded by |L| / I_min (|L| = |I_w w| is conserved); a body that
// rotates under an applied torque and is not a sphere (swing > 0) counts as "can touch".
// If no pair can touch before the first contact, there is no first contact: the scene runs no
// contact code, ever. Two static bodies never touch (overlaps.cpp refuses overlapping ones).
//
// Cost: one test per pair, stopping at the first pair that can touch (a scene with a floor and
// gravity stops at its first dynamic body). Beyond kMaxPairTests the answer is "can touch"
// without looking further (conservative; the reason says so).
#include <string>
#include <vector>

namespace tumble::physics {

struct BodyDef;
struct Model;

// Radius of the smallest sphere about the centre of mass holding the shape (infinite for a plane).
double bounding_radius(const Model& m, int body);

struct TouchReport {
    bool can_touch = false;
    int a = -1, b = -1; // the first pair found that can touch (a < b), or -1
    double when = 0.0;  // s: its closest approach (a == 0), or 0
    long long pairs_checked = 0;
    double min_clearance = 0.0; // m: no pair can touch, the smallest gap left at closest approach
    std::string why;            // one line for `tumble explain`
};

static constexpr long long kMaxPairTests = 1ll << 26;

TouchReport find_touching_pair(const Model& m, const std::vector<BodyDef>& bodies);

} // namespace tumble::physics
