// `tumble plot` (app/plot/, app/cli/plot_command.cpp): the data file holds exactly the series asked
// for, with values computed here from a small states table written by hand (kinetic energies from
// the box and sphere formulas, not from the model); the figure is a PNG or SVG of the size asked
// for with its script and data beside it; a simulate run's scene totals are the sums of its
// bodies'; the legend names each run's integrator; bad input exits 2 naming the file and
// line:column, with nothing written.
#include "app/plot/run_files.h"
#include "app/run/trajectory_reader.h"
#include "app/scene/scene_error.h"
#include "render/png_io.h"
#include "support/cli_runner.h"
#include "support/measured.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

namespace tumble::test {
namespace {

namespace fs = std::filesystem;
using Vec3 = Eigen::Vector3d;

struct Block {
    std::string title;
    std::vector<std::pair<double, double>> points;
};

// The blocks of a data file written by tumble plot: "# title", "# t value", then "t v" lines.
std::vector<Block> read_blocks(const fs::path& dat) {
    std::vector<Block> out;
    std::istringstream in(read_text(dat));
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line == "# t value") continue;
        if (line.starts_with("# ")) {
            out.push_back({line.substr(2), {}});
            continue;
        }
        std::istringstream xy(line);
        double t = 0, v = 0;
        xy >> t >> v;
        out.back().points.emplace_back(t, v);
    }
    return out;
}

const char* kScene = R"({"format_version": 1, "bodies": [
  {"name": "ground", "shape": {"type": "plane"}},
  {"name": "brick", "shape": {"type": "box", "size": [0.2, 0.4, 0.6]}, "mass": 2,
   "position": [0, 0, 2]},
  {"name": "ball", "shape": {"type": "sphere", "radius": 0.1}, "mass": 3,
   "position": [1, 0, 2]}]})";

struct Row {
    double t;
    Vec3 x;
    Eigen::Quaterniond q;
    Vec3 v, w;
};

// Two samples of the brick (body 1) and the ball (body 2), the ground (body 0) at rest.
const Row kBrick[] = {{0.0,
                       {1, 2, 3},
                       Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ())),
                       {1, -2, 0.5},
                       {0.3, -0.2, 1.1}},
                      {0.5,
                       {1.5, 1, 3.25},
                       Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Vec3(1, 2, 2).normalized())),
                       {0.5, -1, 0.25},
                       {-0.4, 0.9, 0.2}}};
const Row kBall[] = {{0.0, {0, 0, 1}, Eigen::Quaterniond::Identity(), {0, 0, -1}, {2, 0, 0}},
                     {0.5, {0, 0, 0.6}, Eigen::Quaterniond::Identity(), {0, 0, -2}, {2, 1, 0}}};

std::string csv_row(int step, int body, const char* name, const Row& r) {
    char buf[512];
    std::snprintf(buf, sizeof buf,
                  "%d,%.17g,%d,\"%s\",%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,"
                  "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n",
                  step, r.t, body, name, r.x.x(), r.x.y(), r.x.z(), r.q.w(), r.q.x(), r.q.y(),
                  r.q.z(), r.v.x(), r.v.y(), r.v.z(), r.w.x(), r.w.y(), r.w.z());
    return buf;
}

std::string states_csv(double w_scale = 1.0) {
    std::string s = std::string(app::kStatesHeader) + "\n";
    for (int k = 0; k < 2; ++k) {
        s += csv_row(k, 0, "ground",
                     {kBrick[k].t, Vec3::Zero(), Eigen::Quaterniond::Identity(), Vec3::Zero(),
                      Vec3::Zero()});
        Row brick = kBrick[k];
        brick.w *= w_scale;
        s += csv_row(k, 1, "brick", brick) + csv_row(k, 2, "ball", kBall[k]);
    }
    return s;
}

const char* kDiagnostics = "step,t,kinetic,potential,energy,px,py,pz,lx,ly,lz\n"
                           "0,0,1.5,0.5,2,3,0,4,0,0,0\n"
                           "1,0.5,2,0.5,2.5,0,0,0,1,2,2\n"
                           "2,1,0.5,0.5,1,0,0,0,0,0,0\n";

// The brick's kinetic energies: 1/2 m v.v and 1/2 w_b . I w_b, I = m (b^2 + c^2) / 12, ...
std::pair<double, double> brick_energy(const Row& r) {
    const double m = 2, a = 0.2, b = 0.4, c = 0.6;
    const Vec3 inertia(m * (b * b + c * c) / 12, m * (a * a + c * c) / 12,
                       m * (a * a + b * b) / 12);
    const Vec3 wb = r.q.conjugate() * r.w;
    return {0.5 * m * r.v.squaredNorm(), 0.5 * wb.dot(inertia.cwiseProduct(wb))};
}

fs::path with_run(const std::string& name = "run.csv") {
    const fs::path dir = scratch_dir();
    write_text(dir / "scene.json", kScene);
    write_text(dir / name, states_csv());
    return dir;
}

TEST(Plot, ADataFileHoldsExactlyTheSeriesAskedForComputedFromTheStates) {
    const fs::path dir = with_run();
    const CliResult r = run_tumble(dir, "plot run.csv --quantity ke_trans,ke_rot --bodies brick "
                                        "--scene scene.json -q -o figs/ke.png");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::vector<Block> blocks = read_blocks(dir / "figs/ke.dat");
    ASSERT_EQ(blocks.size(), 2u);
    EXPECT_EQ(blocks[0].title, "run: brick: ke_trans");
    EXPECT_EQ(blocks[1].title, "run: brick: ke_rot");
    double worst = 0;
    for (int k = 0; k < 2; ++k) {
        const auto [trans, rot] = brick_energy(kBrick[k]);
        ASSERT_EQ(blocks[0].points.size(), 2u);
        EXPECT_EQ(blocks[0].points[k].first, kBrick[k].t);
        worst = std::max({worst, std::abs(blocks[0].points[k].second - trans) / trans,
                          std::abs(blocks[1].points[k].second - rot) / rot});
    }
    TUMBLE_MEASURED(worst, 1e-14);
    EXPECT_LT(worst, 1e-14);
    EXPECT_TRUE(fs::exists(dir / "figs/ke.gp"));
    EXPECT_NE(read_text(dir / "figs/ke.gp").find("data index 1"), std::string::npos);
}

TEST(Plot, TheBallsEnergyAndTheScenesDriftComeFromTheirFormulas) {
    const fs::path dir = with_run();
    write_text(dir / "run.diagnostics.csv", kDiagnostics);
    CliResult r = run_tumble(dir, "plot run.csv --quantity energy --bodies ball --scene "
                                  "scene.json -q -o e.png");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::vector<Block> blocks = read_blocks(dir / "e.dat");
    ASSERT_EQ(blocks.size(), 1u);
    for (int k = 0; k < 2; ++k) { // 1/2 m v.v + 1/2 (2/5 m r^2) w.w + m g z
        const Row& b = kBall[k];
        const double e = 0.5 * 3 * b.v.squaredNorm() + 0.5 * 0.4 * 3 * 0.01 * b.w.squaredNorm() +
                         3 * 9.81 * b.x.z();
        EXPECT_NEAR(blocks[0].points[k].second, e, 1e-12 * e);
    }
    r = run_tumble(dir, "plot run.diagnostics.csv --quantity energy_drift -q -o d.svg");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    blocks = read_blocks(dir / "d.dat");
    ASSERT_EQ(blocks.size(), 1u);
    EXPECT_EQ(blocks[0].title, "run");
    const std::vector<std::pair<double, double>> drift = {{0, 0}, {0.5, 0.25}, {1, -0.5}};
    EXPECT_EQ(blocks[0].points, drift); // (E - E0) / |E0| of 2, 2.5, 1: exact in binary
}

TEST(Plot, SeveralRunsAreOverlaidEachNamedByItsIntegrator) {
    const fs::path dir = with_run("book_symplectic_euler.csv");
    write_text(dir / "book_rk4.csv", states_csv(2.0));
    const CliResult r = run_tumble(dir, "plot book_symplectic_euler.csv book_rk4.csv "
                                        "--quantity w --bodies brick,ball -q -o w.png");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::vector<Block> blocks = read_blocks(dir / "w.dat");
    ASSERT_EQ(blocks.size(), 16u); // 2 runs x 2 bodies x (wx, wy, wz, |w|)
    EXPECT_EQ(blocks[0].title, "symplectic_euler: brick: wx");
    EXPECT_EQ(blocks[7].title, "symplectic_euler: ball: |w|");
    EXPECT_EQ(blocks[8].title, "rk4: brick: wx");
    EXPECT_DOUBLE_EQ(blocks[11].points[1].second, 2 * kBrick[1].w.norm());
    EXPECT_DOUBLE_EQ(blocks[1].points[0].second, kBrick[0].w.y());

    // A glob naming both tables of a run (runs/*.csv) draws it once.
    write_text(dir / "book_rk4.diagnostics.csv", kDiagnostics);
    ASSERT_EQ(run_tumble(dir, "plot book_rk4.csv book_rk4.diagnostics.csv --quantity w --bodies "
                              "ball -q -o once.png")
                  .exit_code,
              0);
    EXPECT_EQ(read_blocks(dir / "once.dat").size(), 4u);

    EXPECT_EQ(app::plot::run_label("runs/splitting4.csv"), "splitting4");
    EXPECT_EQ(app::plot::run_label("top_euler_momentum.csv"), "euler_momentum");
    EXPECT_EQ(app::plot::run_label("fine-rk4-h1.csv"), "rk4");
    EXPECT_EQ(app::plot::run_label("eulerian.csv"), "eulerian"); // no integrator stands alone
    const auto labels = app::plot::run_labels(
        {app::plot::run_files("a/rk4_h1.csv"), app::plot::run_files("a/rk4_h2.csv")});
    EXPECT_EQ(labels, (std::vector<std::string>{"rk4 (rk4_h1)", "rk4 (rk4_h2)"}));
}

TEST(Plot, TheFigureIsAValidPngOrSvgOfTheSizeAskedFor) {
    const fs::path dir = with_run();
    CliResult r = run_tumble(dir, "plot run.csv --quantity w --bodies brick -q --width 640 "
                                  "--height 400 -o w.png");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const render::Image png = render::read_png(dir / "w.png");
    EXPECT_EQ(png.width, 640);
    EXPECT_EQ(png.height, 400);
    int coloured = 0; // the lines: pixels far from grey
    for (std::size_t i = 0; i + 2 < png.rgb.size(); i += 3)
        coloured += std::max({std::abs(png.rgb[i] - png.rgb[i + 1]),
                              std::abs(png.rgb[i + 1] - png.rgb[i + 2])}) > 60;
    EXPECT_GT(coloured, 200);
    r = run_tumble(dir, "plot run.csv --quantity w --bodies brick -q -o w.svg");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string svg = read_text(dir / "w.svg");
    EXPECT_NE(svg.find("width=\"900\" height=\"560\""), std::string::npos) << svg.substr(0, 300);
    EXPECT_EQ(run_shell(dir, "xmllint --noout w.svg").exit_code, 0) << "not well-formed XML";
    EXPECT_EQ(files_in(dir), (std::vector<std::string>{"run.csv", "scene.json", "w.dat", "w.gp",
                                                       "w.png", "w.svg"}));
}

// A simulate run of a scene with a mesh (centre of mass off the body origin, principal axes
// turned): each body's energy, rebuilt from the states and the scene, adds up to the scene's
// energy in the diagnostics.
TEST(Plot, TheBodiesEnergiesOfASimulateRunAddUpToTheScenesTotal) {
    const fs::path dir = scratch_dir();
    ASSERT_EQ(
        run_tumble(dir, "simulate lessons/top_precession --duration 0.05 -q -o top.csv").exit_code,
        0);
    const CliResult r =
        run_tumble(dir, "plot top.csv --quantity energy --bodies table,top --scene "
                        "lessons/top_precession -q -o bodies.png && \"$TUMBLE\" plot top.csv "
                        "--quantity energy -q -o scene.png");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::vector<Block> bodies = read_blocks(dir / "bodies.dat"),
                             scene = read_blocks(dir / "scene.dat");
    ASSERT_EQ(bodies.size(), 2u);
    ASSERT_EQ(scene.size(), 1u);
    ASSERT_EQ(scene[0].points.size(), bodies[1].points.size());
    double worst = 0;
    for (std::size_t k = 0; k < scene[0].points.size(); ++k) {
        const double sum = bodies[0].points[k].second + bodies[1].points[k].second;
        worst = std::max(worst, std::abs(sum - scene[0].points[k].second) /
                                    std::abs(scene[0].points[k].second));
    }
    TUMBLE_MEASURED(worst, 1e-12);
    EXPECT_LT(worst, 1e-12);
}

TEST(Plot, TheReaderNamesTheFileAndLineColumnOfAMalformedTable) {
    const fs::path dir = scratch_dir();
    write_text(dir / "a.csv", std::string(app::kStatesHeader) + "\n0,0,0,\"unterminated\n");
    try {
        app::read_trajectory(dir / "a.csv");
        ADD_FAILURE() << "read a malformed table";
    } catch (const app::SceneError& e) {
        EXPECT_EQ(e.place, "2:7");
        EXPECT_NE(std::string(e.what()).find("unterminated quoted field"), std::string::npos);
    }
    write_text(dir / "b.csv", "step,t,body\n");
    EXPECT_THROW(app::read_trajectory(dir / "b.csv"), app::SceneError);
}

struct BadCase {
    std::string args, message;
};

TEST(Plot, BadInputExitsTwoNamingFileAndPlaceAndWritesNothing) {
    const fs::path dir = with_run();
    write_text(dir / "fig.png", "an earlier figure");
    std::string broken = states_csv();
    broken.replace(broken.find(",1.5,1,3.25,"), 12, ",1.5,1x,3.25,"); // line 6: step 1's brick, y
    write_text(dir / "broken.csv", broken);
    const std::vector<BadCase> cases = {
        {"missing.csv --quantity w --bodies brick", "missing.csv"},
        {"run.csv --quantity spin --bodies brick", "--quantity spin: no such quantity"},
        {"run.csv --quantity w --bodies brik", "no body of that name in run.csv"},
        {"run.csv --quantity w", "a body's quantity: name the body with --bodies"},
        {"run.csv --quantity ke_rot --bodies brick", "name the run's scene with --scene"},
        {"run.csv --quantity ke_trans", "the diagnostics table holds no scene total of it"},
        {"run.csv --quantity ke_rot --bodies brick --scene default", "are not those of the run"},
        {"run.csv --quantity w,energy --bodies brick --scene scene.json",
         "one figure has one axis"},
        {"broken.csv --quantity w --bodies brick",
         "broken.csv:6:21: expected a number, got \"1x\""},
        {"run.csv --quantity energy", "run.diagnostics.csv: file: no such file"},
        {"run.csv --quantity w --bodies brick --labels a,b", "2 labels for 1 runs"},
    };
    const std::vector<std::string> before = files_in(dir);
    for (const BadCase& c : cases) {
        const CliResult r = run_tumble(dir, "plot " + c.args + " -o fig.png");
        EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << "\n" << r.err;
        EXPECT_EQ(files_in(dir), before) << c.args;
    }
    const CliResult r = run_tumble(dir, "plot run.csv --quantity w --bodies brick -o fig.pdf");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("expected a figure name ending in .png or .svg"), std::string::npos);
    EXPECT_EQ(read_text(dir / "fig.png"), "an earlier figure");
}

} // namespace
} // namespace tumble::test
