#include "physics/state_fields.h"

#include "physics/model.h"

#include <string_view>
#include <utility>

namespace tumble::physics {

namespace {

std::string sized(const char* field, std::size_t size, std::size_t expected, const char* what) {
    if (size == expected) return "";
    return std::string(field) + " has " + std::to_string(size) + " entries, expected " +
           std::to_string(expected) + " (" + what + ")";
}

std::string per_body(const Model& m, const State& s) {
    const auto n = static_cast<std::size_t>(m.body_count());
    std::string why;
    for_each_field(s, [&](const char* name, const auto& field) {
        using F = std::decay_t<decltype(field)>;
        if constexpr (!std::is_same_v<F, std::int64_t>) {
            const std::string_view view(name);
            const bool body_array = !view.starts_with("contacts.");
            if (why.empty() && body_array) why = sized(name, field.size(), n, "one per body");
        }
    });
    return why;
}

std::string contact_cache(const Model& m, const ContactCache& c) {
    const auto manifolds = c.pair.size();
    for (const auto& [name, size] :
         {std::pair{"contacts.normal", c.normal.size()},
          std::pair{"contacts.first", c.first.size()}, std::pair{"contacts.count", c.count.size()}})
        if (std::string why = sized(name, size, manifolds, "one per manifold"); !why.empty())
            return why;
    std::size_t next_point = 0;
    for (std::size_t k = 0; k < manifolds; ++k) {
        const std::string at = "contact manifold " + std::to_string(k) + ": ";
        const int a = pair_first(c.pair[k]), b = pair_second(c.pair[k]);
        if (a < 0 || a >= b || b >= m.body_count())
            return at + "bodies " + std::to_string(a) + " and " + std::to_string(b) +
                   " are not two bodies of the model in order";
        if (c.count[k] < 0 || c.count[k] > 4)
            return at + std::to_string(c.count[k]) + " points, expected 0 to 4";
        if (c.first[k] < 0 || static_cast<std::size_t>(c.first[k]) != next_point)
            return at + "its points start at " + std::to_string(c.first[k]) + ", expected " +
                   std::to_string(next_point) + " (each manifold's points follow the last's)";
        next_point += static_cast<std::size_t>(c.count[k]);
    }
    return sized("contacts.points", c.points.size(), next_point, "the manifolds' point counts");
}

std::string sleep_state(const Model& m, const SleepState& sleep) {
    for (std::size_t i = 0; i < sleep.asleep.size(); ++i) {
        if (sleep.asleep[i] > 1)
            return "sleep.asleep of body " + std::to_string(i) + " is " +
                   std::to_string(sleep.asleep[i]) + ", expected 0 or 1";
        if (sleep.island[i] < -1 || sleep.island[i] >= m.body_count())
            return "sleep.island of body " + std::to_string(i) + " is " +
                   std::to_string(sleep.island[i]) + ", expected -1 or a body";
    }
    return "";
}

} // namespace

std::string state_mismatch(const Model& model, const State& state) {
    if (state.step < 0) return "the step counter is negative (" + std::to_string(state.step) + ")";
    if (std::string why = per_body(model, state); !why.empty()) return why;
    if (std::string why = contact_cache(model, state.contacts); !why.empty()) return why;
    return sleep_state(model, state.sleep);
}

} // namespace tumble::physics
