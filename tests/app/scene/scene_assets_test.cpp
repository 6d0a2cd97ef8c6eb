// The built-in scenes and meshes: every file in assets/scenes/ loads (from disk and embedded),
// starts with no body deep inside another, and the sphere-rain scenes are exactly the scene
// built in code that the benchmark and the determinism test run (physics/scenes/sphere_rain.h);
// mesh files resolve next to the scene first, then among the bundled meshes; capsules and meshes
// are drawn as their shapes.
#include "app/run/simulation.h"
#include "app/scene/scene.h"
#include "app/scene/scene_error.h"
#include "app/view/view_builder.h"
#include "physics/scenes/sphere_rain.h"
#include "support/cli_runner.h"
#include "support/measured.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace tumble::test {
namespace {

namespace fs = std::filesystem;
using app::Scene;

fs::path scenes_dir() {
    return fs::path(TUMBLE_SOURCE_DIR) / "assets/scenes";
}

Scene load_file(const fs::path& p) {
    return app::load_scene(read_text(p), p.string());
}

TEST(SceneAssets, EveryFileLoadsFromDiskAndEmbeddedWithoutWarnings) {
    std::vector<std::string> builtin = app::builtin_scene_names();
    int count = 0;
    for (const auto& entry : fs::recursive_directory_iterator(scenes_dir())) {
        if (entry.path().extension() != ".json") continue;
        SCOPED_TRACE(entry.path().string());
        ++count;
        // A scene in a folder is named with it: lessons/intermediate_axis.
        const std::string name =
            fs::relative(entry.path(), scenes_dir()).replace_extension().generic_string();
        Scene from_disk, embedded;
        ASSERT_NO_THROW(from_disk = load_file(entry.path()));
        ASSERT_NO_THROW(embedded = app::load_scene_argument(name));
        EXPECT_FALSE(from_disk.title.empty());
        EXPECT_EQ(from_disk.bodies.size(), embedded.bodies.size());
        EXPECT_TRUE(from_disk.warnings.empty()) << from_disk.warnings.front();
        EXPECT_NE(std::find(builtin.begin(), builtin.end(), name), builtin.end());
    }
    EXPECT_EQ(count, static_cast<int>(builtin.size()));
    EXPECT_GE(count, 9); // default + the scenes of issue 4 (sphere rain twice: shifted, not)
}

// The lessons' scenes (docs/lessons/) are built in under their folder's name, listed after the
// others, and a name is only ever the whole name: "intermediate_axis" alone is no scene.
TEST(SceneAssets, LessonScenesAreBuiltInUnderTheirFoldersName) {
    const std::vector<std::string> builtin = app::builtin_scene_names();
    const auto first_lesson = std::find_if(builtin.begin(), builtin.end(),
                                           [](const auto& n) { return n.starts_with("lessons/"); });
    ASSERT_NE(first_lesson, builtin.end());
    EXPECT_TRUE(std::all_of(first_lesson, builtin.end(),
                            [](const auto& n) { return n.starts_with("lessons/"); }));
    const Scene s = app::load_scene_argument("lessons/intermediate_axis");
    EXPECT_EQ(s.source, "builtin:lessons/intermediate_axis.json");
    EXPECT_EQ(app::scene_name(s), "intermediate_axis"); // default outputs: intermediate_axis.mp4
    EXPECT_EQ(app::load_scene_argument("builtin:lessons/intermediate_axis.json").bodies.size(),
              s.bodies.size());
    EXPECT_THROW(app::load_scene_argument("intermediate_axis"), app::SceneError);
    EXPECT_THROW(app::load_scene_argument("elsewhere/intermediate_axis"), app::SceneError);
    const CliResult r = run_tumble(scratch_dir(), "scenes");
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_NE(r.out.find("lessons/intermediate_axis "), std::string::npos) << r.out;
}

void expect_same_scene(const Scene& json, const scenes::Scene& code) {
    ASSERT_EQ(json.bodies.size(), code.bodies.size());
    EXPECT_EQ(json.world.dt, code.world.dt);
    EXPECT_EQ(json.world.gravity, code.world.gravity);
    EXPECT_EQ(json.world.contact.sleeping, code.world.contact.sleeping);
    EXPECT_EQ(json.duration, code.duration);
    int differing = 0;
    for (std::size_t i = 0; i < code.bodies.size(); ++i) {
        const physics::BodyDef &a = json.bodies[i], &b = code.bodies[i];
        const bool same = a.shape.kind == b.shape.kind && a.shape.radius == b.shape.radius &&
                          a.shape.half_extents == b.shape.half_extents && a.motion == b.motion &&
                          a.position == b.position &&
                          a.orientation.coeffs() == b.orientation.coeffs() &&
                          a.material.friction == b.material.friction &&
                          a.material.restitution == b.material.restitution &&
                          (a.motion == physics::Motion::Static || a.mass == b.mass);
        differing += !same;
        EXPECT_TRUE(same) << "body " << i << " at " << a.position.transpose() << " vs "
                          << b.position.transpose();
        if (differing > 3) break;
    }
    TUMBLE_MEASURED(differing, 0);
}

TEST(SceneAssets, ABuiltInSceneLoadsByItsNameAndAsMessagesNameIt) {
    // Summaries and errors call a built-in scene "builtin:dominoes.json": pasted back, it loads.
    const app::Scene by_name = app::load_scene_argument("dominoes");
    for (const char* arg : {"builtin:dominoes", "builtin:dominoes.json"}) {
        const app::Scene s = app::load_scene_argument(arg);
        EXPECT_EQ(s.source, by_name.source) << arg;
        EXPECT_EQ(s.bodies.size(), by_name.bodies.size()) << arg;
    }
    EXPECT_THROW(app::load_scene_argument("builtin:no_such_scene"), app::SceneError);
}

TEST(SceneAssets, SphereRainIsExactlyTheSceneBuiltInCode) {
    expect_same_scene(load_file(scenes_dir() / "sphere_rain.json"), scenes::sphere_rain(10, true));
    expect_same_scene(load_file(scenes_dir() / "sphere_columns.json"),
                      scenes::sphere_rain(10, false));
}

TEST(SceneAssets, MeshFilesResolveBesideTheSceneFirstThenAmongTheBundledOnes) {
    const fs::path dir = scratch_dir();
    const std::string scene = R"({"format_version": 1, "bodies": [
        {"shape": {"type": "mesh", "file": "top.obj"}, "density": 1000}]})";
    write_text(dir / "s.json", scene);
    const Scene bundled = load_file(dir / "s.json");
    ASSERT_EQ(bundled.meshes.size(), 1u);
    // A unit cube (volume 1 m^3) of the same name beside the scene wins.
    write_text(dir / "top.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\n"
                                "v 0 1 1\nf 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\n"
                                "f 4 1 5 8\n");
    const Scene local = load_file(dir / "s.json");
    EXPECT_DOUBLE_EQ(local.bodies[0].mass, 1000.0);         // density x 1 m^3
    EXPECT_EQ(local.bodies[0].mesh->triangles.size(), 12u); // quads split in two
    EXPECT_LT(bundled.bodies[0].mass, 1.0);                 // the 8 cm top: about 0.12 kg
    TUMBLE_MEASURED(bundled.bodies[0].mass, 1.0);
}

TEST(SceneAssets, MeshBodiesShareOneDrawnMeshPerFileAndScale) {
    const Scene s = app::load_scene(R"({"format_version": 1, "bodies": [
        {"shape": {"type": "plane"}},
        {"shape": {"type": "mesh", "file": "top.obj"}, "position": [0, 0, 0.1]},
        {"shape": {"type": "mesh", "file": "top.obj"}, "position": [1, 0, 0.1]},
        {"shape": {"type": "mesh", "file": "top.obj", "scale": 2}, "position": [2, 0, 0.1]}]})",
                                    "inline.json");
    ASSERT_EQ(s.meshes.size(), 2u);
    EXPECT_EQ(s.looks[1].mesh_id, s.looks[2].mesh_id);
    EXPECT_NE(s.looks[1].mesh_id, s.looks[3].mesh_id);
    EXPECT_EQ(s.bodies[1].mesh, s.bodies[2].mesh);
    // Twice the size: 8 times the volume, so 8 times the mass at the same density.
    EXPECT_NEAR(s.bodies[3].mass / s.bodies[1].mass, 8.0, 1e-12);
}

TEST(SceneAssets, ACapsuleIsDrawnAsACylinderBetweenTwoSpheresAndAMeshAsItsTriangles) {
    const Scene s = app::load_scene(R"({"format_version": 1, "bodies": [
        {"shape": {"type": "capsule", "radius": 0.1, "length": 0.6}, "position": [0, 0, 1]},
        {"shape": {"type": "mesh", "file": "top.obj"}, "position": [1, 0, 0]}]})",
                                    "inline.json");
    EXPECT_DOUBLE_EQ(s.bodies[0].shape.half_length, 0.3); // "length" is the straight part
    const app::Simulation sim = app::make_simulation(s, s.world.dt);
    render::SceneView view;
    app::build_view(s, sim.model, sim.state, view);
    ASSERT_EQ(view.instances.size(), 4u);
    const render::Instance &cyl = view.instances[0], &cap0 = view.instances[1],
                           &cap1 = view.instances[2], &mesh = view.instances[3];
    EXPECT_EQ(cyl.mesh, render::MeshKind::Cylinder);
    EXPECT_FLOAT_EQ(cyl.transform[2][2], 0.3f); // unit cylinder z in [-1, 1] -> half length
    EXPECT_FLOAT_EQ(cyl.transform[0][0], 0.1f);
    EXPECT_EQ(cap0.mesh, render::MeshKind::Sphere);
    EXPECT_EQ(cap1.mesh, render::MeshKind::Sphere);
    EXPECT_FLOAT_EQ(cap0.transform[3][2], 0.7f); // centres of the end caps at z = 1 -+ 0.3
    EXPECT_FLOAT_EQ(cap1.transform[3][2], 1.3f);
    EXPECT_FLOAT_EQ(cap0.transform[0][0], 0.1f);
    EXPECT_EQ(mesh.mesh, render::MeshKind::Custom);
    ASSERT_EQ(view.meshes.size(), 1u);
    EXPECT_EQ(view.meshes[mesh.mesh_id], s.meshes[0]);
    EXPECT_EQ(view.meshes[0]->indices.size(), 3 * s.bodies[1].mesh->triangles.size());
}

} // namespace
} // namespace tumble::test
