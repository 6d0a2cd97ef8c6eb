#pragma once
// `tumble render --compare euler,rk4,...` (compare_command.cpp).
#include "app/cli/render_setup.h"

namespace tumble::app {

// Renders the scene once per integrator named by --compare, tiles side by side. Throws what
// app/cli/failure.h maps.
int run_compare(const RenderCommand& cmd);

} // namespace tumble::app
