#pragma once
// The unit cone, for arrow heads: base circle of radius 1 in the z = 0 plane, apex at (0, 0, 1),
// base closed by a flat cap. Smooth side normals (the slanted surface normal, for a cone of
// height 1 and radius 1 tilted 45 degrees out of the base plane), flat cap normal -z. Drawn as a
// MeshKind::Custom mesh (scene_view.h).
#include "render/mesh_data.h"

namespace tumble::render {

MeshData make_cone(int segments = 24);

} // namespace tumble::render
