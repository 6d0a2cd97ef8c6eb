#pragma once
// Capturing and restoring a State field by field: the one list of everything a later step reads,
// for whatever saves states outside the process (the app's checkpoint files; physics knows
// nothing of files). A restored State continues bit-identically when every field below comes back
// with the same bits, because step() reads nothing else: the StepWorkspace holds only scratch
// (contact_stage.h), and the Model is rebuilt from the same scene.
//
// for_each_field(state, visit) calls visit(name, field) for each field in a fixed order, with
// field one of: std::int64_t, std::vector<Vec3>, std::vector<Quat>, std::vector<std::uint64_t>,
// std::vector<int>, std::vector<std::uint8_t>, std::vector<double>, std::vector<CachedPoint>.
// A CachedPoint's own members come from for_each_field(point, visit) (Vec3, double,
// std::uint32_t). `state` may be const (saving) or not (restoring).
//
// The failure mode this guards against: a field added to State (or to the contact cache or the
// sleep state) and not listed here would be dropped from checkpoints, and a resumed run would
// drift from an unbroken one without any error. The static_asserts below fail to compile when the
// size of one of these structs changes; whoever changes it lists the new field here and updates
// the size.
#include "physics/state.h"

#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

namespace tumble::physics {

static_assert(sizeof(Vec3) == 3 * sizeof(double) && sizeof(Quat) == 4 * sizeof(double),
              "Vec3 and Quat are stored as their doubles");
static_assert(sizeof(std::vector<int>) == 24, "the sizes below count 24-byte vectors");
static_assert(sizeof(State) == 8 + 5 * 24 + 5 * 24 + 3 * 24,
              "State changed: list the new field in for_each_field(State) and update this size");
static_assert(sizeof(ContactCache) == 5 * 24,
              "ContactCache changed: list the new field in for_each_field(State)");
static_assert(sizeof(SleepState) == 3 * 24,
              "SleepState changed: list the new field in for_each_field(State)");
static_assert(sizeof(CachedPoint) == 24 + 8 + 8 + 8 + 24,
              "CachedPoint changed: list the new member in for_each_field(CachedPoint)");

template <class S, class Visit>
requires std::is_same_v<std::remove_const_t<S>, State>
void for_each_field(S& s, Visit&& visit) {
    visit("step", s.step);
    visit("x", s.x);
    visit("q", s.q);
    visit("v", s.v);
    visit("w", s.w);
    visit("x_carry", s.x_carry);
    visit("contacts.pair", s.contacts.pair);
    visit("contacts.normal", s.contacts.normal);
    visit("contacts.first", s.contacts.first);
    visit("contacts.count", s.contacts.count);
    visit("contacts.points", s.contacts.points);
    visit("sleep.asleep", s.sleep.asleep);
    visit("sleep.slow_time", s.sleep.slow_time);
    visit("sleep.island", s.sleep.island);
}

template <class P, class Visit>
requires std::is_same_v<std::remove_const_t<P>, CachedPoint>
void for_each_field(P& p, Visit&& visit) {
    visit("point", p.point);
    visit("separation", p.separation);
    visit("id", p.id);
    visit("normal_impulse", p.normal_impulse);
    visit("friction_impulse", p.friction_impulse);
}

// Why `state` cannot be a state of `model` (the first inconsistency found), or "" when it can:
// per-body arrays of the model's body count, a contact cache whose manifolds name bodies of the
// model in order (a < b) with 1..4 points each, laid out one after another in `points`, sleep
// flags of 0 or 1. What a restored State must pass before step() may read it: step() trusts its
// State and would index out of bounds otherwise.
std::string state_mismatch(const Model& model, const State& state);

} // namespace tumble::physics
