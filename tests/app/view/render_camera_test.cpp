// Cameras from the scene file: each mode is the function of time (and of the followed body) that
// docs/scene-format.md describes, and bad camera sections fail at their JSON path.
#include "app/scene/camera_rig_reader.h"
#include "app/scene/scene.h"
#include "app/scene/scene_error.h"
#include "app/view/camera.h"

#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

#include <string>

namespace tumble::app {
namespace {

CameraRig rig_from(const std::string& camera_json) {
    const nlohmann::json j = nlohmann::json::parse(camera_json);
    CameraRig rig;
    read_camera_rig(JsonReader(j, "test.json", "/render/camera"), rig);
    return rig;
}

float distance(glm::vec3 a, glm::vec3 b) {
    return glm::length(a - b);
}

TEST(CameraRig, FixedCameraIgnoresTime) {
    const CameraRig rig =
        rig_from(R"({"position": [1, 2, 3], "target": [0, 0, 1], "fov_deg": 30})");
    const render::Camera c = camera_at(rig, 7.5, {});
    EXPECT_EQ(c.position, glm::vec3(1, 2, 3));
    EXPECT_EQ(c.target, glm::vec3(0, 0, 1));
    EXPECT_EQ(c.fov_y_deg, 30.0f);
}

TEST(CameraRig, OrbitKeepsRadiusAndHeightAndTurnsOncePerPeriod) {
    const CameraRig rig = rig_from(R"({"position": [3, 0, 2], "target": [0, 0, 1],
                                       "orbit": {"period": 8}})");
    for (double t : {0.0, 1.0, 2.0, 5.5}) {
        const render::Camera c = camera_at(rig, t, {});
        EXPECT_NEAR(std::hypot(c.position.x, c.position.y), 3.0, 1e-5) << t;
        EXPECT_NEAR(c.position.z, 2.0, 1e-6) << t;
        EXPECT_EQ(c.target, glm::vec3(0, 0, 1));
    }
    EXPECT_LT(distance(camera_at(rig, 0.0, {}).position, {3, 0, 2}), 1e-5f); // starts where given
    EXPECT_LT(distance(camera_at(rig, 2.0, {}).position, {0, 3, 2}), 1e-5f); // quarter turn, ccw
    EXPECT_LT(distance(camera_at(rig, 8.0, {}).position, {3, 0, 2}), 1e-5f);
    const CameraRig cw = rig_from(R"({"position": [3, 0, 2], "target": [0, 0, 1],
                                      "orbit": {"period": -8, "radius": 5, "height": 1}})");
    EXPECT_LT(distance(camera_at(cw, 2.0, {}).position, {0, -5, 2}), 1e-5f);
}

TEST(CameraRig, FollowRidesAlongOrTracksFromAFixedPlace) {
    CameraRig rig = rig_from(R"({"follow": {"body": "ball", "offset": [0, -2, 1]}})");
    render::Camera c = camera_at(rig, 0.0, {5, 6, 7});
    EXPECT_EQ(c.target, glm::vec3(5, 6, 7));
    EXPECT_EQ(c.position, glm::vec3(5, 4, 8));
    rig = rig_from(R"({"position": [1, 1, 1], "follow": {"body": 2, "track": true}})");
    c = camera_at(rig, 0.0, {5, 6, 7});
    EXPECT_EQ(c.position, glm::vec3(1, 1, 1));
    EXPECT_EQ(c.target, glm::vec3(5, 6, 7));
    resolve_followed_body(rig, {"ground", "book", "ball"}, "test.json");
    EXPECT_EQ(rig.follow_body, 2);
}

TEST(CameraRig, PathPassesThroughItsKeysAndEasesAtTheEnds) {
    const CameraRig rig = rig_from(R"({"path": [
        {"t": 0, "position": [0, -4, 1], "target": [0, 0, 1], "fov_deg": 40},
        {"t": 2, "position": [4, 0, 2], "target": [0, 0, 1]},
        {"t": 5, "position": [0, 4, 1], "target": [0, 0, 0.5], "fov_deg": 30}]})");
    EXPECT_LT(distance(camera_at(rig, 0.0, {}).position, {0, -4, 1}), 1e-6f);
    EXPECT_LT(distance(camera_at(rig, 2.0, {}).position, {4, 0, 2}), 1e-6f);
    EXPECT_LT(distance(camera_at(rig, 5.0, {}).position, {0, 4, 1}), 1e-6f);
    EXPECT_LT(distance(camera_at(rig, 9.0, {}).position, {0, 4, 1}), 1e-6f); // holds the last key
    EXPECT_FLOAT_EQ(camera_at(rig, 5.0, {}).fov_y_deg, 30.0f);
    EXPECT_FLOAT_EQ(camera_at(rig, 2.0, {}).fov_y_deg, 45.0f); // the default, no fov given
    // Eases in: a small step after the first key moves far less than the average speed would.
    const float early = distance(camera_at(rig, 0.02, {}).position, {0, -4, 1});
    EXPECT_LT(early, 0.02f * distance({0, -4, 1}, {4, 0, 2}) / 2.0f * 0.2f);
    // Smooth through the middle key: equal small steps either side move about equally far.
    const float before = distance(camera_at(rig, 1.99, {}).position, {4, 0, 2});
    const float after = distance(camera_at(rig, 2.01, {}).position, {4, 0, 2});
    EXPECT_NEAR(before / after, 1.0f, 0.5f);
}

TEST(CameraRig, BadCamerasFailAtTheirPath) {
    auto message = [](const std::string& json) {
        try {
            rig_from(json);
        } catch (const SceneError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message(R"({"orbit": {"period": 5}, "path": []})").find("at most one"),
              std::string::npos);
    EXPECT_NE(message(R"({"orbit": {"period": 0}})").find("/render/camera/orbit/period"),
              std::string::npos);
    EXPECT_NE(message(R"({"orbit": {}})").find("period"), std::string::npos);
    EXPECT_NE(message(R"({"path": [{"t": 0, "position": [1, 0, 0], "target": [0, 0, 0]}]})")
                  .find("at least two"),
              std::string::npos);
    EXPECT_NE(message(R"({"path": [{"t": 1, "position": [1, 0, 0], "target": [0, 0, 0]},
                                   {"t": 1, "position": [2, 0, 0], "target": [0, 0, 0]}]})")
                  .find("/render/camera/path/1/t"),
              std::string::npos);
    EXPECT_NE(message(R"({"follow": {"bdy": "x"}})").find("follow"), std::string::npos);
    CameraRig rig = rig_from(R"({"follow": {"body": "nobody"}})");
    try {
        resolve_followed_body(rig, {"ground", "ball"}, "test.json");
        FAIL() << "expected a SceneError";
    } catch (const SceneError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("/render/camera/follow/body"), std::string::npos) << what;
        EXPECT_NE(what.find("ground, ball"), std::string::npos) << what;
    }
}

} // namespace
} // namespace tumble::app
