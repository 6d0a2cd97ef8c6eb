#pragma once
// Ambient occlusion where bodies meet the ground and each other: an analytic method, no screen
// pass. Every body stands in for itself as an ellipsoid (an "occluder"); the darkening it casts
// on a nearby surface point is the fraction of that point's sky it hides, in closed form.
//
// The formula. A sphere of radius r whose centre is at distance d from a surface point, in a
// direction at angle theta from the point's normal n, hides the fraction
//     occ = cos(theta) (r / d)^2
// of the cosine-weighted sky hemisphere (the form factor of a sphere seen from a differential
// patch; exact while the sphere is wholly above the point's horizon, Quilez, "Sphere ambient
// occlusion", 2006). A sphere resting on the ground is tangent to it, so for ground points it is
// exact everywhere: at horizontal distance x from the contact, d^2 = x^2 + r^2 and
// cos(theta) = r / d, so occ = r^3 / d^3 (1 at the contact, 0.35 at x = r).
// An ellipsoid is a sphere seen through a linear map: with A taking the ellipsoid to the unit
// sphere, the point goes to A (p - c) and its normal to A^-T n (normals transform by the inverse
// transpose); the sphere formula is then applied there. This is exact for spheres and a close,
// smooth approximation for the rest.
//
// Which ellipsoid. Each shape is replaced by the uniform ellipsoid with the same inertia
// (Legendre's equivalent ellipsoid): semi-axes a_i^2 = 5 / (2 m) (I_j + I_k - I_i). For a box of
// half extents h that gives sqrt(5/3) h; for a cylinder of radius r and half length l,
// sqrt(5/4) r across and sqrt(5/3) l along (with I from the usual formulas: the mass is where
// the occlusion comes from). A mesh is treated as the box of its bounds.
//
// Where it is drawn.
//   - Body on body: each body's fragments sum the two occluders nearest it (lit.frag), found
//     here on the CPU per frame; the darkening scales the light that comes from the sky
//     (ambient and reflections), which is what the occluder hides.
//   - Body on ground: one decal per body near a plane, a square on the plane around the body's
//     foot, shaded by ao_decal.frag and multiplied into the colour already there.
// Occlusion fades to 0 between 2 and 3 radii (in the ellipsoid's unit space), where it is under
// 1/4: beyond that nothing is looked up, so the cost is bounded per pixel.
#include "render/scene_view.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace tumble::render {

// How far an occluder reaches, in its unit-sphere radii: occlusion is 0 beyond.
constexpr float kOcclusionReach = 3.0f;

// The equivalent ellipsoid's semi-axes relative to each unit mesh's half extents.
constexpr float kBoxToEllipsoid = 1.2909944f;     // sqrt(5/3)
constexpr float kCylinderAcross = 1.1180340f;     // sqrt(5/4)
constexpr float kCylinderAlong = kBoxToEllipsoid; // sqrt(5/3)

struct Occluder {
    glm::vec3 centre{0.0f};
    glm::mat3 to_unit{1.0f}; // A: world offsets from the centre -> the unit sphere
    float bound = 0.0f;      // largest semi-axis, metres (the ellipsoid's bounding sphere)
    std::int32_t body = -1;  // Instance::body of the shape it stands for
};

// The three vec4 rows a shader reads: (row i of A, centre[i]). The "no occluder" rows put a
// unit sphere a kilometre away, whose occlusion is 0 after the fade: shaders need no branch.
using PackedOccluder = std::array<glm::vec4, 3>;
PackedOccluder pack(const Occluder& o);
PackedOccluder no_occluder();

// The occluder of one instance; `unit_half_extent` is the custom mesh's (ignored otherwise).
// Planes occlude nothing: check `kind` before calling.
Occluder occluder_of(MeshKind kind, const glm::mat4& transform, glm::vec3 unit_half_extent);

// For each receiver (a centre and a bounding radius, and the body it belongs to), the indices of
// the two occluders whose reach comes nearest to it, -1 where fewer than two reach it. Occluders
// of the receiver's own body are skipped. Sweep over x (O(n log n) plus the pairs that overlap),
// ties broken by index: the same input gives the same answer. `order` is scratch (kept by the
// caller between frames, so a warmed-up frame allocates nothing).
struct Receiver {
    glm::vec3 centre;
    float bound;
    std::int32_t body;
};
void nearest_occluders(std::span<const Occluder> occluders, std::span<const Receiver> receivers,
                       std::vector<std::array<std::int32_t, 2>>& out,
                       std::vector<std::int32_t>& order);

// One ground decal: the unit square [-1, 1]^2 of the plane mesh placed on a plane under an
// occluder (`model`), and the occluder.
struct Decal {
    glm::mat4 model;
    PackedOccluder occluder;
};

// A plane instance (Instance::transform of MeshKind::Plane) and the occluders near enough to
// darken it: appends one decal per occluder within reach above the plane and inside its square.
void add_ground_decals(const glm::mat4& plane, std::span<const Occluder> occluders,
                       std::vector<Decal>& out);

} // namespace tumble::render
