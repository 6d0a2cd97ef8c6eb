#include "physics/passes.h"

namespace tumble::physics {

void force_all_passes(Model& m) {
    m.all_passes = true;
    m.passes.gravity = true;
    m.passes.applied_loads = true;
    m.passes.gyroscopic = true;
    m.passes.contacts = true;
}

} // namespace tumble::physics
