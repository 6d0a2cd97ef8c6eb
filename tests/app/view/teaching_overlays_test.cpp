// The teaching overlays (issue 16) against the mechanics they draw:
//   - Poinsot's construction: the ellipsoid touches the invariable plane at w, tangentially; the
//     plane stays fixed and perpendicular to L with the integrators that keep T and L; the
//     polhode closes after one period of the exact (Jacobi) solution;
//   - strip charts: each sample is the quantity at that frame's state, the y range holds every
//     sample, and the tiles of a comparison share it;
//   - trails: the points are the centres of mass at the past frame times, fading with age.
#include "app/run/frame_source.h"
#include "app/run/simulation.h"
#include "app/run/timeline.h"
#include "app/scene/scene.h"
#include "app/view/poinsot.h"
#include "app/view/strip_chart.h"
#include "app/view/trails.h"
#include "physics/diagnostics.h"
#include "physics/exact/free_rigid_body.h"
#include "render/png_io.h"
#include "support/cli_runner.h"
#include "support/measured.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

namespace tumble::app {
namespace {

using physics::Quat;
using physics::Vec3;

// The default scene's book alone: a torque-free box spun near its middle axis.
std::string book_scene(const std::string& integrator, double dt, double duration) {
    return R"({"format_version": 1, "world": {"integrator": ")" + integrator + R"(", "dt": )" +
           std::to_string(dt) + R"(, "duration": )" + std::to_string(duration) +
           R"(, "gravity": [0, 0, 0]},
      "bodies": [{"name": "book", "shape": {"type": "box", "size": [0.22, 0.05, 0.30]},
                  "mass": 0.8, "angular_velocity": [6.0, 0.05, 0.05],
                  "angular_velocity_frame": "body"}]})";
}

TEST(Poinsot, TheEllipsoidTouchesTheInvariablePlaneAtWTangentially) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int trial = 0; trial < 100; ++trial) {
        const Vec3 I(0.5 + std::abs(u(rng)), 0.5 + std::abs(u(rng)), 0.5 + std::abs(u(rng)));
        const Quat q = Quat(u(rng), u(rng), u(rng), u(rng)).normalized();
        const Vec3 w(3 * u(rng), 3 * u(rng), 3 * u(rng));
        const PoinsotGeometry g = poinsot_geometry(I, q, w);
        // Independently: T and L from their definitions, I_w = R I_body R^T.
        const physics::Mat3 R = q.toRotationMatrix();
        const physics::Mat3 Iw = R * I.asDiagonal() * R.transpose();
        const Vec3 L = Iw * w;
        const double two_t = w.dot(Iw * w);
        // The contact point is w; it lies on the ellipsoid x . I_w x = 2T ...
        EXPECT_NEAR((g.contact - w).norm(), 0.0, 1e-15);
        EXPECT_NEAR(g.contact.dot(Iw * g.contact), two_t, 1e-12 * two_t);
        // ... and on the plane perpendicular to L at 2T / |L| ...
        EXPECT_NEAR((g.normal - L.normalized()).norm(), 0.0, 1e-14);
        EXPECT_NEAR(g.contact.dot(g.normal), g.distance, 1e-12 * g.distance);
        EXPECT_NEAR(g.distance, two_t / L.norm(), 1e-12 * g.distance);
        // ... where the ellipsoid's normal (the gradient I_w x) is the plane's: tangent.
        EXPECT_NEAR((Iw * g.contact).normalized().cross(g.normal).norm(), 0.0, 1e-12);
        // Semi-axes: the points sqrt(2T / I_i) e_i are on the ellipsoid.
        for (int i = 0; i < 3; ++i)
            EXPECT_NEAR(I[i] * g.semi_axes[i] * g.semi_axes[i], two_t, 1e-12 * two_t);
    }
}

// The plane's normal and distance over a run, worst change from t = 0, relative.
struct PlaneDrift {
    double normal = 0.0, distance = 0.0;
};
PlaneDrift plane_drift(const std::string& integrator, double seconds) {
    const Scene scene = load_scene(book_scene(integrator, 1.0 / 240, seconds), "book.json");
    Simulation sim = make_simulation(scene, scene.world.dt);
    const auto g0 = poinsot_geometry(sim.model.inertia[0], sim.state.q[0], sim.state.w[0]);
    PlaneDrift d;
    const int steps = int(std::lround(seconds * 240));
    for (int k = 0; k < steps; ++k) {
        sim.step();
        const auto g = poinsot_geometry(sim.model.inertia[0], sim.state.q[0], sim.state.w[0]);
        d.normal = std::max(d.normal, (g.normal - g0.normal).norm());
        d.distance = std::max(d.distance, std::abs(g.distance - g0.distance) / g0.distance);
    }
    return d;
}

TEST(Poinsot, ThePlaneStaysFixedWithTheIntegratorsThatKeepTAndL) {
    // midpoint keeps T and L exactly (every quadratic invariant): the plane to round-off.
    const PlaneDrift mid = plane_drift("midpoint", 10.0);
    TUMBLE_MEASURED(mid.normal, 1e-12);
    TUMBLE_MEASURED(mid.distance, 1e-12);
    EXPECT_LT(mid.normal, 1e-12);
    EXPECT_LT(mid.distance, 1e-12);
    // splitting keeps L exactly and T within O(h^2): the normal to round-off, the distance close.
    const PlaneDrift split = plane_drift("splitting", 10.0);
    TUMBLE_MEASURED(split.normal, 1e-12);
    TUMBLE_MEASURED(split.distance, 1e-4);
    EXPECT_LT(split.normal, 1e-12);
    EXPECT_LT(split.distance, 1e-4);
    // euler keeps neither: the plane wanders (this is what the picture shows going wrong).
    const PlaneDrift euler = plane_drift("euler", 10.0);
    TUMBLE_MEASURED(euler.distance, 1e-2);
    EXPECT_GT(euler.distance, 1e-2);
}

TEST(Poinsot, ThePolhodeClosesAfterOnePeriodOfTheExactSolution) {
    const Scene scene = load_scene(book_scene("splitting4", 1.0 / 960, 10.0), "book.json");
    Simulation sim = make_simulation(scene, scene.world.dt);
    const exact::ExactFreeRigidBody exact(sim.model.inertia[0], sim.state.q[0], sim.state.w[0]);
    const double period = exact.body_period();
    ASSERT_TRUE(std::isfinite(period));
    ASSERT_LT(period, 8.0);
    const double h = sim.model.dt;
    PoinsotConstruction construction(scene, sim.model, sim.state, 0);
    const Vec3 w0 = sim.state.q[0].conjugate() * sim.state.w[0];
    // Step to the last step before one period, then the remainder exactly.
    const auto steps = std::int64_t(std::floor(period / h));
    double farthest = 0.0; // how far the polhode wanders from its start meanwhile
    for (std::int64_t k = 0; k < steps; ++k) {
        sim.step();
        farthest = std::max(farthest, (sim.state.q[0].conjugate() * sim.state.w[0] - w0).norm());
    }
    physics::Model rest = sim.model;
    rest.dt = period - double(steps) * h;
    physics::State s = sim.state;
    physics::step(rest, s);
    const Vec3 w1 = s.q[0].conjugate() * s.w[0];
    const double gap = (w1 - w0).norm() / w0.norm();
    TUMBLE_MEASURED(gap, 1e-6);
    EXPECT_LT(gap, 1e-6) << "period " << period << " s";
    EXPECT_GT(farthest / w0.norm(), 1.0); // it went round: w swung through the body and back
}

TEST(StripChart, SamplesAreTheQuantitiesAtEachFrameAndTheScaleHoldsThemAll) {
    const Scene scene = load_scene(book_scene("rk4", 1.0 / 240, 2.0), "book.json");
    Simulation sim = make_simulation(scene, scene.world.dt);
    ChartSettings c{{Quantity::Energy, Quantity::AngularVelocityBody}, 0, "book", 0.0};
    ChartHistory history(c, sim.model, sim.state);
    ChartScale scale(2);
    scale.include(history, 0);
    for (int frame = 1; frame <= 60; ++frame) {
        for (int k = 0; k < 4; ++k) sim.step();
        history.record(sim.model, sim.state);
        scale.include(history, history.samples() - 1);
        // Independently: T = 1/2 w . I_w w and w_body = R^T w.
        const Vec3 wb = sim.state.q[0].conjugate() * sim.state.w[0];
        const double t = 0.5 * wb.dot(sim.model.inertia[0].cwiseProduct(wb));
        EXPECT_NEAR(history.value(0, 0, history.samples() - 1), t, 1e-12);
        for (int i = 0; i < 3; ++i)
            EXPECT_NEAR(history.value(1, i, history.samples() - 1), wb[i], 1e-12);
    }
    for (std::size_t p = 0; p < 2; ++p)
        for (std::size_t k = 0; k < history.samples(); ++k)
            for (int i = 0; i < (p == 0 ? 1 : 3); ++i) {
                EXPECT_GE(history.value(p, i, k), scale.range(p).lo);
                EXPECT_LE(history.value(p, i, k), scale.range(p).hi);
            }
    // The chart draws a title, both axes' ends, and one line per component.
    render::Canvas canvas;
    const render::OverlayFont font = render::overlay_font(1280, 720);
    const glm::vec2 size = chart_panel_size(font, 1280, 720);
    const std::vector<ScreenBox> boxes = {{{800, 300}, glm::vec2(800, 300) + size},
                                          {{800, 500}, glm::vec2(800, 500) + size}};
    draw_charts(history, scale, 0.25, 2.0, font, boxes, canvas);
    EXPECT_EQ(canvas.rects.size(), 2u);
    EXPECT_GE(canvas.strips.size(), 2u + 1u + 3u);
    for (const glm::vec2& p : canvas.points) { // inside the image
        EXPECT_TRUE(p.x >= 0 && p.x <= 1280 && p.y >= 0 && p.y <= 720);
    }
}

TEST(StripChart, NiceRangesHoldTheDataInStepsOfOneTwoOrFive) {
    for (auto [lo, hi] : {std::pair{0.0, 1.0}, {-3.7, 12.2}, {1e-7, 3e-7}, {-2e6, -1e6}}) {
        const render::NiceRange r = render::nice_range(lo, hi);
        EXPECT_LT(r.lo, lo);
        EXPECT_GT(r.hi, hi);
        // A step of 1, 2 or 5 x 10^k, and whole steps at both ends.
        const double decade = std::pow(10.0, std::floor(std::log10(r.step) + 1e-9));
        const double m = r.step / decade;
        EXPECT_TRUE(std::abs(m - 1) < 1e-9 || std::abs(m - 2) < 1e-9 || std::abs(m - 5) < 1e-9)
            << r.step;
        EXPECT_NEAR(r.lo / r.step, std::round(r.lo / r.step), 1e-9);
        EXPECT_NEAR(r.hi / r.step, std::round(r.hi / r.step), 1e-9);
    }
    // A flat line gets a span of its own size around it.
    const render::NiceRange flat = render::nice_range(5.0, 5.0);
    EXPECT_LT(flat.lo, 5.0);
    EXPECT_GT(flat.hi, 5.0);
}

// Issue 30: data within +-6 rad/s was drawn in a -10..20 box, because the scale padded an already
// padded range each time it grew. The box must hold the data with at most one nice step of slack
// at each end, at every frame, however the data grows; steps of 1, 2 or 5 x 10^k near a tenth of
// the span.
TEST(StripChart, TheBoxHoldsTheDataWithAtMostOneStepOfSlack) {
    // The intermediate-axis book: w_body's components swing between -6 and 6 rad/s.
    const Scene scene = load_scene(book_scene("splitting", 1.0 / 240, 12.0), "book.json");
    Simulation sim = make_simulation(scene, scene.world.dt);
    ChartSettings c{{Quantity::AngularVelocityBody, Quantity::EnergyDrift}, 0, "book", 0.0};
    ChartHistory history(c, sim.model, sim.state);
    ChartScale scale(2);
    scale.include(history, 0);
    double lo[2], hi[2]; // of the samples so far, from t = 0
    for (std::size_t p = 0; p < 2; ++p) lo[p] = hi[p] = history.value(p, 0, 0);
    for (int i = 1; i < 3; ++i)
        lo[0] = std::min(lo[0], history.value(0, i, 0)),
        hi[0] = std::max(hi[0], history.value(0, i, 0));
    double worst_slack = 0.0; // in steps
    for (int frame = 1; frame <= 720; ++frame) {
        for (int k = 0; k < 4; ++k) sim.step();
        history.record(sim.model, sim.state);
        scale.include(history, history.samples() - 1);
        for (std::size_t p = 0; p < 2; ++p) {
            for (int i = 0; i < (p == 0 ? 3 : 1); ++i) {
                const double v = history.value(p, i, history.samples() - 1);
                lo[p] = std::min(lo[p], v), hi[p] = std::max(hi[p], v);
            }
            const render::NiceRange& r = scale.range(p);
            ASSERT_LE(r.lo, lo[p]) << "frame " << frame;
            ASSERT_GE(r.hi, hi[p]) << "frame " << frame;
            if (hi[p] - lo[p] <= 1e-6 * std::max(std::abs(lo[p]), std::abs(hi[p]))) continue;
            worst_slack = std::max({worst_slack, (lo[p] - r.lo) / r.step, (r.hi - hi[p]) / r.step});
            // The step is a nice one near a tenth of the span (4 to 12 intervals in the box).
            const double intervals = (r.hi - r.lo) / r.step;
            EXPECT_GE(intervals, 4.0 - 1e-9) << "frame " << frame;
            EXPECT_LE(intervals, 12.0 + 1e-9) << "frame " << frame;
        }
    }
    TUMBLE_MEASURED(worst_slack, 1.0);
    EXPECT_LE(worst_slack, 1.0 + 1e-9);
    // The components reach +-6 rad/s: the box is -8..8 at most (steps of 2), never -10..20.
    const render::NiceRange& w = scale.range(0);
    TUMBLE_MEASURED(w.hi - w.lo, 16.0);
    EXPECT_LE(w.hi - w.lo, 16.0 + 1e-9);
}

TEST(StripChart, ComparedTilesShareOneScale) {
    // Euler's energy drifts, splitting's stays: one shared range must hold both.
    const Scene a = load_scene(book_scene("euler", 1.0 / 60, 4.0), "a.json");
    const Scene b = load_scene(book_scene("splitting", 1.0 / 60, 4.0), "b.json");
    Simulation sa = make_simulation(a, a.world.dt), sb = make_simulation(b, b.world.dt);
    ChartSettings c{{Quantity::EnergyDrift}, 0, "book", 0.0};
    ChartHistory ha(c, sa.model, sa.state), hb(c, sb.model, sb.state);
    ChartScale shared(1);
    for (int k = 0; k < 240; ++k) {
        sa.step(), sb.step();
        ha.record(sa.model, sa.state), hb.record(sb.model, sb.state);
        shared.include(ha, ha.samples() - 1), shared.include(hb, hb.samples() - 1);
    }
    const double euler_drift = std::abs(ha.value(0, 0, ha.samples() - 1));
    const double split_drift = std::abs(hb.value(0, 0, hb.samples() - 1));
    TUMBLE_MEASURED(euler_drift, 1e-2);
    EXPECT_GT(euler_drift, 100 * split_drift);
    EXPECT_GE(shared.range(0).hi - shared.range(0).lo, euler_drift);
}

// The chart's energies from their definitions (app/scene/quantity.h, the catalogue tumble plot
// shares): a thrown, spinning brick, T = 1/2 m v.v + 1/2 w . I_w w, V = - m g . x, E = T + V.
TEST(StripChart, KineticAndPotentialEnergyFollowTheirDefinitions) {
    const std::string json = R"({"format_version": 1, "world": {"dt": 0.01, "duration": 1},
      "bodies": [{"name": "brick", "shape": {"type": "box", "size": [0.2, 0.4, 0.6]}, "mass": 2,
                  "position": [0, 0, 1], "velocity": [1, 0, 3], "angular_velocity": [0, 0, 2]}]})";
    const Scene scene = load_scene(json, "brick.json");
    Simulation sim = make_simulation(scene, 0.01);
    ChartSettings c{{Quantity::Kinetic, Quantity::Potential, Quantity::Energy}, -1, "", 0.0};
    ChartHistory history(c, sim.model, sim.state);
    const double m = 2.0;
    // Principal moments of the box, I = m (b^2 + c^2) / 12, ...; w along z, the body's z axis.
    const double iz = m * (0.2 * 0.2 + 0.4 * 0.4) / 12;
    double worst = 0.0;
    for (int k = 0; k < 50; ++k) {
        sim.step();
        history.record(sim.model, sim.state);
        const Vec3 v = sim.state.v[0], x = sim.state.x[0], w = sim.state.w[0];
        const double t = 0.5 * m * v.squaredNorm() + 0.5 * iz * w.squaredNorm();
        const double potential = m * 9.81 * x.z(); // the default g = (0, 0, -9.81) m/s^2
        const std::size_t i = history.samples() - 1;
        worst = std::max({worst, std::abs(history.value(0, 0, i) - t) / t,
                          std::abs(history.value(1, 0, i) - potential) / potential,
                          std::abs(history.value(2, 0, i) - (t + potential)) / (t + potential)});
    }
    TUMBLE_MEASURED(worst, 1e-14);
    EXPECT_LT(worst, 1e-14);
}

TEST(Trails, PointsAreTheCentresAtPastFramesFadingWithAge) {
    const std::string json = R"({"format_version": 1, "world": {"dt": 0.01},
      "bodies": [{"name": "ball", "shape": {"type": "sphere", "radius": 0.1},
                  "velocity": [1, 0, 3], "color": "#ff0000"}]})";
    const Scene scene = load_scene(json, "ball.json");
    Simulation sim = make_simulation(scene, 0.01);
    Trails trails(scene, sim.model, sim.state, 11, -1);
    std::vector<Vec3> centres{sim.state.x[0]};
    for (int frame = 1; frame <= 25; ++frame) {
        sim.step();
        trails.record(sim.model, sim.state);
        centres.push_back(sim.state.x[0]);
    }
    render::SceneView view;
    trails.add(view);
    const render::Polylines& lines = view.lines;
    ASSERT_EQ(lines.strips.size(), 1u);
    ASSERT_EQ(lines.strips[0].count, 11u); // the last 11 frames
    for (std::uint32_t k = 0; k < 11; ++k) {
        const Vec3& c = centres[centres.size() - 11 + k];
        const glm::vec3 p = lines.points[k];
        EXPECT_NEAR(p.x, c.x(), 1e-6);
        EXPECT_NEAR(p.z, c.z(), 1e-6);
        if (k > 0) {
            EXPECT_GT(lines.colors[k].a, lines.colors[k - 1].a); // newer is stronger
        }
    }
    EXPECT_EQ(lines.colors[0].a, 0.0f);
}

} // namespace
} // namespace tumble::app

namespace tumble::app {
namespace {

using test::CliResult;
using test::run_tumble;
using test::scratch_dir;

TEST(TeachingCli, EachOverlayDrawsWhereItShouldAndBadNamesAreRefused) {
    const auto dir = scratch_dir();
    auto still = [&](const std::string& flags, const std::string& name) {
        const CliResult r = run_tumble(
            dir, "render default --time 3 --width 320 --height 180 -q -o " + name + " " + flags);
        EXPECT_EQ(r.exit_code, 0) << flags << r.err;
        return render::read_png(dir / name);
    };
    const render::Image plain = still("", "plain.png");
    // The charts sit at the corners (those hiding least of the bodies, app/view/overlay_layout.h):
    // they change many pixels, none in the middle fifth of the image.
    const render::Image chart = still("--chart energy,w_body --chart-body book", "chart.png");
    int changed = 0;
    for (int y = 0; y < 180; ++y)
        for (int x = 0; x < 320; ++x) {
            if (std::equal(plain.row(y) + 3 * x, plain.row(y) + 3 * x + 3, chart.row(y) + 3 * x))
                continue;
            ++changed;
            EXPECT_FALSE(x >= 128 && x < 192 && y >= 72 && y < 108)
                << "chart drew at " << x << "," << y;
        }
    EXPECT_GT(changed, 2000);
    for (const char* flags :
         {"--trails", "--trail-axis y", "--poinsot book", "--overlay-body book"})
        EXPECT_NE(still(flags, "x.png").rgb, plain.rgb) << flags;
    // A still of frame k shows what frame k of a run shows: the history is sampled at every
    // frame time, drawn or not.
    const render::Image a = still("--chart energy --trails --poinsot book --duration 3.1", "a.png");
    const CliResult run = run_tumble(dir, "render default --width 320 --height 180 --duration 3.1 "
                                          "-q -o frames/ --chart energy --trails --poinsot book");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(render::read_png(dir / "frames" / "000180.png").rgb, a.rgb);

    for (const char* bad :
         {"--chart nope", "--chart-body nobody --chart w", "--poinsot ground", "--trail-axis q"}) {
        const CliResult r =
            run_tumble(dir, std::string("render default --frame 0 -q -o b.png ") + bad);
        EXPECT_EQ(r.exit_code, 2) << bad;
        EXPECT_NE(r.err.find("tumble: error:"), std::string::npos) << r.err;
    }
    EXPECT_NE(
        run_tumble(dir, "render default --frame 0 -q -o b.png --poinsot ground").err.find("static"),
        std::string::npos);
}

} // namespace
} // namespace tumble::app
