#include "physics/scenes/state_hash.h"

#include <cstddef>

namespace tumble::scenes {

std::uint64_t state_hash(const physics::State& s) {
    std::uint64_t h = 1469598103934665603ull;
    auto mix = [&](const void* p, std::size_t n) {
        const auto* b = static_cast<const unsigned char*>(p);
        for (std::size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
    };
    for (std::size_t i = 0; i < s.x.size(); ++i) {
        mix(s.x[i].data(), sizeof(double) * 3);
        mix(s.q[i].coeffs().data(), sizeof(double) * 4);
        mix(s.v[i].data(), sizeof(double) * 3);
        mix(s.w[i].data(), sizeof(double) * 3);
    }
    return h;
}

} // namespace tumble::scenes
