// Lesson 7 (docs/lessons/07-inertia-tensor.md): the 30-60-90 set square of
// assets/meshes/set_square.obj (a right triangle with legs a along x and b along y, thickness t),
// whose mass properties the model takes from its triangles (physics/mesh.h), against
//  - the triangle's closed forms about its centroid (a/3, b/3): I_xx = m (b^2 / 18 + t^2 / 12),
//    I_yy = m (a^2 / 18 + t^2 / 12), I_zz = m (a^2 + b^2) / 18, and the product of inertia
//    P_xy = integral of x y dm = m a b / 12 about the right angle, P_xy - m (a/3)(b/3) = -m a b /
//    36 about the centroid (the parallel-axis theorem), entering the tensor as I_xy = -P_xy;
//  - seed 001's sum over particles, I = sum m_i [y^2 + z^2, -x y, ...], over a grid of point
//    masses filling the prism (the midpoint rule: its error falls as the grid's spacing squared).
// Then the principal axes by diagonalising the in-plane block, tan(2 alpha) = 2 I_xy / (I_xx -
// I_yy), and the run of the lesson's scene: spun about a leg or about the seed's axis the set
// square wobbles, about the principal axis it does not.
#include "lesson_support.h"

#include "physics/math.h"

#include <Eigen/Eigenvalues>

#include <array>
#include <numbers>

namespace tumble::test {
namespace {

constexpr const char* kLesson = "07-inertia-tensor.md";
constexpr double kDensity = 1190, kThick = 0.01, kDeg = 180 / std::numbers::pi;
// The legs as the mesh writes them (scripts/make-meshes.py: 0.30 and 0.30 tan(30 degrees) to nine
// decimals).
constexpr double kA = 0.30, kB = 0.173205081;

struct Tensor {
    double mass;
    physics::Vec3 com;
    physics::Mat3 about_com;
};

// The closed forms for a right-triangle plate of legs a, b and thickness t.
Tensor triangle(double a, double b) {
    const double m = kDensity * a * b / 2 * kThick;
    Tensor t{m, {a / 3, b / 3, 0}, physics::Mat3::Zero()};
    t.about_com(0, 0) = m * (b * b / 18 + kThick * kThick / 12);
    t.about_com(1, 1) = m * (a * a / 18 + kThick * kThick / 12);
    t.about_com(2, 2) = m * (a * a + b * b) / 18;
    t.about_com(0, 1) = t.about_com(1, 0) = m * a * b / 36; // -P_xy, P_xy = -m a b / 36
    return t;
}

// Seed 001's sum: point masses on an n x n x 4 grid filling the prism, each weighing its cell
// (cells cut by the hypotenuse split into the two triangles they hold, weighed at their
// centroids). `seed_signs`: the off-diagonal entries as seed 000's matrix writes them, +sum m x y.
physics::Mat3 particle_sum(int n, bool seed_signs) {
    const Tensor t = triangle(kA, kB);
    physics::Mat3 sum = physics::Mat3::Zero();
    const double dx = kA / n, dy = kB / n;
    const auto add = [&](double x, double y, double area) {
        for (int k = 0; k < 4; ++k) {
            const double z = (k + 0.5) * kThick / 4 - kThick / 2;
            const physics::Vec3 r = physics::Vec3(x, y, z) - t.com;
            const double m = kDensity * area * kThick / 4;
            physics::Mat3 cell =
                m * (r.squaredNorm() * physics::Mat3::Identity() - r * r.transpose());
            if (seed_signs)
                for (int i = 0; i < 3; ++i)
                    for (int j = 0; j < 3; ++j)
                        if (i != j) cell(i, j) = -cell(i, j);
            sum += cell;
        }
    };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            // Cell (i, j) in units of (dx, dy): fully inside when i + j + 2 <= n, on the
            // hypotenuse when i + j + 1 == n (its lower-left half is inside), outside otherwise.
            const double x = (i + 0.5) * dx, y = (j + 0.5) * dy;
            if (i + j + 2 <= n)
                add(x, y, dx * dy);
            else if (i + j + 1 == n)
                add(i * dx + dx / 3, j * dy + dy / 3, dx * dy / 2);
        }
    return sum;
}

// Angle (rad) of the smallest principal axis of the in-plane block from the x axis, in
// (-90, 90] degrees.
double min_axis_angle(const physics::Mat3& t) {
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(t.topLeftCorner<2, 2>());
    physics::Vec3 e(eig.eigenvectors()(0, 0), eig.eigenvectors()(1, 0), 0.0);
    if (e.x() < 0) e = -e;
    return std::atan2(e.y(), e.x());
}

TEST(Lessons, TheSetSquaresTensorHasItsProductsOfInertiaWithTheirSigns) {
    const Tensor t = triangle(kA, kB);
    const app::Scene scene = lesson_scene("set_square");
    const app::Simulation sim = lesson_simulation(scene);
    const int b = body_index(scene, "principal");
    // The model's mass, centre, moments and axes (from the mesh's triangles) against the closed
    // forms.
    const Eigen::SelfAdjointEigenSolver<physics::Mat3> eig(t.about_com);
    const double moments_error = (sim.model.inertia[b] - eig.eigenvalues()).cwiseAbs().maxCoeff() /
                                 eig.eigenvalues().maxCoeff();
    TUMBLE_MEASURED(moments_error, 1e-9);
    EXPECT_LT(moments_error, 1e-9);
    EXPECT_LT(std::abs(sim.model.mass[b] / t.mass - 1), 1e-9);
    EXPECT_LT((sim.model.com_offset[b] - t.com).norm(), 1e-12);
    const physics::Vec3 model_axis = sim.model.body_from_mass[b] * physics::Vec3::UnitX();
    const double alpha = min_axis_angle(t.about_com);
    const double axis_error =
        std::abs(std::abs(model_axis.dot(physics::Vec3(std::cos(alpha), std::sin(alpha), 0))) - 1);
    TUMBLE_MEASURED(axis_error, 1e-12);
    EXPECT_LT(axis_error, 1e-12);

    // Seed 001's sum over particles converges to the closed forms; with seed 000's signs it gives
    // the same diagonal and the opposite products.
    const physics::Mat3 particles = particle_sum(400, false), seed = particle_sum(400, true);
    const double sum_error =
        (particles - t.about_com).cwiseAbs().maxCoeff() / t.about_com.maxCoeff();
    TUMBLE_MEASURED(sum_error, 1e-4);
    EXPECT_LT(sum_error, 1e-4);
    EXPECT_NEAR(seed(0, 1), -particles(0, 1), 1e-15);

    // The parallel-axis theorem for the product: about the right angle and about the centroid.
    const double product_corner = t.mass * kA * kB / 12;
    const double product_centre = product_corner - t.mass * (kA / 3) * (kB / 3);
    EXPECT_NEAR(-product_centre, t.about_com(0, 1), 1e-15);

    constexpr double kgcm2 = 1e4; // kg m^2 -> kg cm^2
    expect_quoted(kLesson, "mass", t.mass);
    expect_quoted(kLesson, "com_x", 100 * t.com.x());
    expect_quoted(kLesson, "com_y", 100 * t.com.y());
    expect_quoted(kLesson, "product_at_corner", kgcm2 * product_corner);
    expect_quoted(kLesson, "product_at_centre", kgcm2 * product_centre);
    expect_quoted(kLesson, "I_xx", kgcm2 * t.about_com(0, 0));
    expect_quoted(kLesson, "I_yy", kgcm2 * t.about_com(1, 1));
    expect_quoted(kLesson, "I_zz", kgcm2 * t.about_com(2, 2));
    expect_quoted(kLesson, "I_xy", kgcm2 * t.about_com(0, 1));
    expect_quoted(kLesson, "I1", kgcm2 * eig.eigenvalues()[0]);
    expect_quoted(kLesson, "I2", kgcm2 * eig.eigenvalues()[1]);
    expect_quoted(kLesson, "I3", kgcm2 * eig.eigenvalues()[2]);
    expect_quoted(kLesson, "principal_angle", kDeg * alpha);

    // Seed 000's matrix: its smallest axis is the mirror image of the true one, and the body's
    // moment about it is not a principal moment.
    const double seed_alpha = min_axis_angle(seed);
    const physics::Vec3 seed_axis(std::cos(seed_alpha), std::sin(seed_alpha), 0);
    expect_quoted(kLesson, "seed_angle", kDeg * seed_alpha);
    expect_quoted(kLesson, "seed_axis_true_moment", kgcm2 * seed_axis.dot(t.about_com * seed_axis));

    // The catch: a dumbbell along the diagonal of the xy plane has no moment about its own axis.
    // Point masses m/2 at +-a (1, 1, 0) / sqrt(2): the right tensor gives I n = 0 along it, the
    // seed's gives n . I n = m a^2, the moment about an axis across it.
    const double m = 1, half = 1;
    physics::Mat3 rod = physics::Mat3::Zero();
    for (const double sgn : {-half, half}) {
        const physics::Vec3 r = sgn * physics::Vec3(1, 1, 0) / std::sqrt(2.0);
        rod += m / 2 * (r.squaredNorm() * physics::Mat3::Identity() - r * r.transpose());
    }
    physics::Mat3 rod_seed = rod;
    rod_seed(0, 1) = rod_seed(1, 0) = -rod(0, 1);
    const physics::Vec3 n = physics::Vec3(1, 1, 0).normalized();
    EXPECT_LT((rod * n).norm(), 1e-15);
    expect_quoted(kLesson, "rod_seed_moment", n.dot(rod_seed * n) / (m * half * half));
}

// The run: w at t = 0 and how far it wanders (world frame) over the scene's 8 s.
struct Spin {
    double w_l_angle, wander;
};

Spin spin_of(const app::Scene& scene, const std::string& name) {
    app::Simulation sim = lesson_simulation(scene);
    const int b = body_index(scene, name);
    const physics::Vec3 w0 = sim.state.w[b];
    const physics::Quat q = sim.state.q[b];
    const physics::Vec3 l0 = q * sim.model.inertia[b].cwiseProduct(q.conjugate() * w0);
    Spin s{angle_between(w0, l0), 0.0};
    const auto steps = static_cast<int>(std::lround(scene.duration / sim.model.dt));
    for (int k = 0; k < steps; ++k) {
        sim.step();
        s.wander = std::max(s.wander, angle_between(sim.state.w[b], w0));
    }
    return s;
}

TEST(Lessons, OnlyTheSetSquareSpunAboutAPrincipalAxisKeepsItsSpin) {
    const app::Scene scene = lesson_scene("set_square");
    const Tensor t = triangle(kA, kB);
    const double alpha = min_axis_angle(t.about_com);
    // The scene spins "principal" about the axis computed here (to the 11 digits it writes).
    const int p = body_index(scene, "principal");
    const physics::Vec3 wb =
        scene.bodies[p].orientation.conjugate() * scene.bodies[p].angular_velocity;
    EXPECT_LT((wb.normalized() - physics::Vec3(std::cos(alpha), std::sin(alpha), 0)).norm(), 1e-10);

    const Spin edge = spin_of(scene, "leg"), seed = spin_of(scene, "seed"),
               principal = spin_of(scene, "principal");
    TUMBLE_MEASURED(principal.wander, 1e-8);
    EXPECT_LT(principal.w_l_angle, 1e-10); // w along a principal axis: L = I w is parallel to it
    EXPECT_LT(principal.wander, 1e-8);     // and nothing turns it
    EXPECT_GT(edge.wander, 0.5);
    EXPECT_GT(seed.wander, 0.5);
    expect_quoted(kLesson, "leg_w_L_angle", kDeg * edge.w_l_angle);
    expect_quoted(kLesson, "seed_w_L_angle", kDeg * seed.w_l_angle);
    expect_quoted(kLesson, "leg_wander", kDeg * edge.wander);
    expect_quoted(kLesson, "seed_wander", kDeg * seed.wander);
}

// Exercises: the perpendicular-axis theorem with thickness (I_zz = I_xx + I_yy - 2 sum m z^2 =
// I_xx + I_yy - m t^2 / 6), and a 45 degree set square, whose axes lie at 45 degrees by symmetry.
TEST(Lessons, TheInertiaTensorExercisesHaveTheAnswersGiven) {
    const Tensor t = triangle(kA, kB);
    const double predicted = t.about_com(0, 0) + t.about_com(1, 1) - t.mass * kThick * kThick / 6;
    EXPECT_LT(std::abs(predicted - t.about_com(2, 2)), 1e-15);
    expect_quoted(kLesson, "perpendicular_axis_correction", 1e4 * t.mass * kThick * kThick / 6);
    expect_quoted(kLesson, "even_legs_angle", kDeg * min_axis_angle(triangle(kA, kA).about_com));
}

} // namespace
} // namespace tumble::test
