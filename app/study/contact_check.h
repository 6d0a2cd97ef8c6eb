#pragma once
// `tumble explain`'s check against the contact stability map (contact_stability.h): which of the
// map's cases a scene resembles, and whether each holds at the scene's own integrator, step and
// substeps. Each resemblance is judged from the initial state:
//   stack   the tallest column of dynamic boxes resting on each other (3 or more);
//   ratio   a dynamic body resting on a lighter one, heavier by 10 times or more;
//   bullet  a dynamic body at 1 m/s or more while a static box is in the scene;
//   top     a dynamic body spinning at 100 rad/s or more in a scene with contacts;
//   rest    a dynamic sphere resting on a plane.
// The case checked is the map's next one up (a column of 7 is checked as a stack of 10), run for
// real at the scene's settings; a failure becomes a warning naming the measured outcome.
#include "app/study/contact_stability.h"
#include "physics/model.h"
#include "physics/state.h"

#include <string>
#include <vector>

namespace tumble::app::study {

struct ContactCheck {
    ContactCase c;
    std::string resemblance; // what in the scene matched ("column of 7 boxes: body 3 to 9")
    ContactRun run;          // the map's case at the scene's settings
};

// The cases `model` resembles, each run at model.integrator, model.dt and model.contact.substeps.
// None when the contact stage is off.
std::vector<ContactCheck> check_contact_regions(const physics::Model& model,
                                                const physics::State& state);

} // namespace tumble::app::study
