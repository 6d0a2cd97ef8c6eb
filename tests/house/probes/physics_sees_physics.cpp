// Must compile: the control for the probes beside it. A physics file sees physics' own headers
// with the same build settings, so the probes fail for the reason they name and no other.
#include "physics/model.h"

int tumble_probe_physics_sees_physics() {
    return tumble::physics::Model{}.body_count();
}
