// Mass properties against textbook formulas: the capsule (cylinder + two hemispheres) and the
// exact polyhedral integrals of closed meshes (Mirtich 1996 / Eberly 2002), which must reproduce
// a box, a tetrahedron and a moved, turned box to round-off, and approach a sphere and a cylinder
// as their facets shrink.
#include "physics/build.h"
#include "physics/hull.h"
#include "physics/mesh.h"
#include "support/measured.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace tumble::physics {
namespace {

constexpr double kPi = std::numbers::pi;

TriangleMesh box_mesh(const Vec3& h) {
    TriangleMesh m;
    for (int k = 0; k < 8; ++k)
        m.vertices.emplace_back(k & 1 ? h.x() : -h.x(), k & 2 ? h.y() : -h.y(),
                                k & 4 ? h.z() : -h.z());
    const int quads[6][4] = {{1, 3, 7, 5}, {0, 4, 6, 2}, {2, 6, 7, 3},
                             {0, 1, 5, 4}, {4, 5, 7, 6}, {0, 2, 3, 1}};
    for (const auto& q : quads) {
        m.triangles.push_back({q[0], q[1], q[2]});
        m.triangles.push_back({q[0], q[2], q[3]});
    }
    return m;
}

// A UV sphere of radius r: `rings` latitude bands, `segments` around; closed, wound outward.
TriangleMesh uv_sphere(double r, int segments, int rings) {
    TriangleMesh m;
    m.vertices.emplace_back(0, 0, -r);
    for (int i = 1; i < rings; ++i) {
        const double th = kPi * i / rings - kPi / 2;
        for (int j = 0; j < segments; ++j) {
            const double ph = 2 * kPi * j / segments;
            m.vertices.emplace_back(r * std::cos(th) * std::cos(ph),
                                    r * std::cos(th) * std::sin(ph), r * std::sin(th));
        }
    }
    m.vertices.emplace_back(0, 0, r);
    const int top = static_cast<int>(m.vertices.size()) - 1;
    auto at = [&](int ring, int j) { return 1 + (ring - 1) * segments + (j % segments); };
    for (int j = 0; j < segments; ++j) m.triangles.push_back({0, at(1, j + 1), at(1, j)});
    for (int i = 1; i < rings - 1; ++i)
        for (int j = 0; j < segments; ++j) {
            m.triangles.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1)});
            m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i + 1, j)});
        }
    for (int j = 0; j < segments; ++j)
        m.triangles.push_back({top, at(rings - 1, j), at(rings - 1, j + 1)});
    return m;
}

double max_abs(const Mat3& m) {
    return m.cwiseAbs().maxCoeff();
}

TEST(MassProperties, CapsuleMatchesCylinderPlusHemispheres) {
    // r = 0.1, L = 0.6, density 1000: textbook parts, written out independently.
    const double r = 0.1, len = 0.6, rho = 1000.0;
    const Shape cap = Shape::capsule(r, len / 2);
    const double mc = rho * kPi * r * r * len, mh = rho * 2.0 / 3.0 * kPi * r * r * r;
    const double m = mc + 2 * mh;
    EXPECT_NEAR(shape_volume(cap) * rho, m, 1e-12 * m);
    // About the axis: a cylinder (m r^2 / 2) and a whole sphere (2/5 m r^2).
    const double axial = 0.5 * mc * r * r + 0.4 * (2 * mh) * r * r;
    // Across: cylinder m (L^2/12 + r^2/4); each hemisphere 83/320 m r^2 about its own centre of
    // mass, which sits L/2 + 3r/8 from the capsule centre.
    const double d = len / 2 + 3 * r / 8;
    const double across =
        mc * (len * len / 12 + r * r / 4) + 2 * mh * (83.0 / 320.0 * r * r + d * d);
    const Vec3 I = shape_principal_inertia(cap, m);
    const double err = std::max({std::abs(I.z() - axial) / axial, std::abs(I.x() - across) / across,
                                 std::abs(I.y() - across) / across});
    TUMBLE_MEASURED(err, 1e-12);
    EXPECT_LT(err, 1e-12);
}

TEST(MassProperties, BoxMeshIsExact) {
    const Vec3 h(0.3, 0.2, 0.1);
    const MeshMassProperties p = mesh_mass_properties(box_mesh(h));
    const double v = 8 * h.prod();
    EXPECT_NEAR(p.volume, v, 1e-15);
    EXPECT_LT(p.centroid.norm(), 1e-15);
    const Vec3 textbook = shape_principal_inertia(Shape::box(h), v); // unit density: m = V
    const double err = max_abs(p.inertia - Mat3(textbook.asDiagonal())) / textbook.maxCoeff();
    TUMBLE_MEASURED(err, 1e-13);
    EXPECT_LT(err, 1e-13);
}

TEST(MassProperties, MovedAndTurnedBoxKeepsItsInertia) {
    // Translation moves the centroid and nothing else; rotation turns the tensor: R I R^T.
    const Vec3 h(0.3, 0.2, 0.1), t(1.5, -2.0, 0.7);
    const Mat3 r = Quat(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized())).toRotationMatrix();
    TriangleMesh m = box_mesh(h);
    for (Vec3& v : m.vertices) v = r * v + t;
    const MeshMassProperties p = mesh_mass_properties(m);
    const Vec3 textbook = shape_principal_inertia(Shape::box(h), 8 * h.prod());
    const Mat3 expected = r * textbook.asDiagonal() * r.transpose();
    const double err = max_abs(p.inertia - expected) / textbook.maxCoeff();
    TUMBLE_MEASURED(err, 1e-12);
    EXPECT_LT(err, 1e-12);
    EXPECT_LT((p.centroid - t).norm(), 1e-13);
}

TEST(MassProperties, TetrahedronMatchesClosedForm) {
    // The corner tetrahedron (0,0,0), (a,0,0), (0,a,0), (0,0,a): V = a^3/6, centroid a/4 (1,1,1);
    // about the origin int x^2 dV = V a^2/10 and int xy dV = V a^2/20, so about the centroid
    // Ixx = 3/40 m a^2 and Ixy = +1/80 m a^2 (m = V at unit density).
    const double a = 2.0;
    TriangleMesh m;
    m.vertices = {Vec3(0, 0, 0), Vec3(a, 0, 0), Vec3(0, a, 0), Vec3(0, 0, a)};
    m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    ASSERT_FALSE(check_closed_mesh(m).has_value());
    const MeshMassProperties p = mesh_mass_properties(m);
    const double v = a * a * a / 6;
    EXPECT_NEAR(p.volume, v, 1e-14);
    EXPECT_LT((p.centroid - Vec3::Constant(a / 4)).norm(), 1e-14);
    // About the origin: int x^2 dV = a^5/60, int xy dV = a^5/120. Shift to the centroid.
    const double xx = a * a * a * a * a / 60 - v * (a / 4) * (a / 4);
    const double xy = a * a * a * a * a / 120 - v * (a / 4) * (a / 4);
    const double diag = 2 * xx, off = -xy;
    const double err =
        std::max(std::abs(p.inertia(0, 0) - diag), std::abs(p.inertia(0, 1) - off)) / diag;
    TUMBLE_MEASURED(err, 1e-13);
    EXPECT_LT(err, 1e-13);
}

TEST(MassProperties, FacetedSphereConvergesToTwoFifthsMR2) {
    // The inscribed polyhedron's error shrinks as the facets do (about as 1 / segments^2).
    double previous = 1.0;
    for (int n : {16, 32, 64}) {
        const MeshMassProperties p = mesh_mass_properties(uv_sphere(1.0, n, n / 2));
        const double ratio = p.inertia(2, 2) / (0.4 * p.volume); // I / (2/5 m r^2), r = 1
        const double err = std::abs(p.inertia(2, 2) / (0.4 * p.volume * 1.0) - 1.0);
        std::printf("segments %d: V / (4/3 pi) = %.6f, I / (2/5 m r^2) = %.6f\n", n,
                    p.volume / (4.0 / 3.0 * kPi), ratio);
        EXPECT_LT(err, previous);
        previous = err;
    }
    TUMBLE_MEASURED(previous, 0.01);
    EXPECT_LT(previous, 0.01);
}

TEST(MassProperties, MeshBodyUsesCentroidAndPrincipalAxes) {
    // A box mesh offset from its origin and turned: build_model() puts the centre of mass at the
    // centroid and finds the box's principal moments (in some order) and axes.
    const Vec3 h(0.3, 0.2, 0.1), t(0.2, 0.1, -0.3);
    const Quat turn(Eigen::AngleAxisd(0.4, Vec3(0, 0, 1)));
    auto mesh = std::make_shared<TriangleMesh>(box_mesh(h));
    for (Vec3& v : mesh->vertices) v = turn * v + t;
    BodyDef b;
    b.shape = Shape::mesh();
    b.mesh = mesh;
    b.mass = 2.0;
    BodyDef other; // something to meet: the contact stage is built too
    other.position = Vec3(5, 0, 0);
    const Model m = build_model({}, {b, other});
    EXPECT_LT((m.com_offset[0] - t).norm(), 1e-12);
    Vec3 moments = m.inertia[0];
    std::sort(moments.data(), moments.data() + 3);
    Vec3 expected = shape_principal_inertia(Shape::box(h), 2.0);
    std::sort(expected.data(), expected.data() + 3);
    const double err = (moments - expected).norm() / expected.norm();
    TUMBLE_MEASURED(err, 1e-12);
    EXPECT_LT(err, 1e-12);
    EXPECT_EQ(m.hulls[m.hull[0]].faces.size(), 6u); // coplanar triangles merged into 6 faces
}

TEST(MassProperties, RefusesOpenInvertedAndNonConvexMeshes) {
    TriangleMesh open = box_mesh(Vec3(1, 1, 1));
    open.triangles.pop_back();
    ASSERT_TRUE(check_closed_mesh(open).has_value());
    EXPECT_NE(check_closed_mesh(open)->find("not closed"), std::string::npos);

    TriangleMesh inverted = box_mesh(Vec3(1, 1, 1));
    for (auto& t : inverted.triangles) std::swap(t[1], t[2]);
    ASSERT_TRUE(check_closed_mesh(inverted).has_value());
    EXPECT_NE(check_closed_mesh(inverted)->find("wound inward"), std::string::npos);

    // A box with its top centre pushed down: closed, positive volume, not convex.
    TriangleMesh dented = box_mesh(Vec3(1, 1, 1));
    dented.vertices.emplace_back(0, 0, 0.5);
    const int c = static_cast<int>(dented.vertices.size()) - 1;
    dented.triangles.erase(dented.triangles.begin() + 8, dented.triangles.begin() + 10); // +z quad
    for (auto [u, v] : {std::pair{4, 5}, std::pair{5, 7}, std::pair{7, 6}, std::pair{6, 4}})
        dented.triangles.push_back({u, v, c});
    ASSERT_FALSE(check_closed_mesh(dented).has_value()) << *check_closed_mesh(dented);
    ConvexHull hull;
    const auto why = make_mesh_hull(dented, hull);
    ASSERT_TRUE(why.has_value());
    EXPECT_NE(why->find("not convex"), std::string::npos) << *why;
}

} // namespace
} // namespace tumble::physics
