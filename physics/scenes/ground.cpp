#include "physics/scenes/ground.h"

namespace tumble::scenes {

physics::BodyDef ground(double friction) {
    physics::BodyDef g;
    g.shape = physics::Shape::plane();
    g.motion = physics::Motion::Static;
    g.material.friction = friction;
    return g;
}

} // namespace tumble::scenes
