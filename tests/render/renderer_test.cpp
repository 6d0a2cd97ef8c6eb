// The renderer draws what the SceneView says, the right way up, the same way every time.
#include "render/renderer.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace tumble::render {
namespace {

struct Rgb {
    int r, g, b;
};

Rgb pixel(const Image& img, int x, int y) {
    const std::uint8_t* p = img.row(y) + 3 * x;
    return {p[0], p[1], p[2]};
}

bool reddish(Rgb c) {
    return c.r > 100 && c.r > 2 * c.g && c.r > 2 * c.b;
}

// Writes a binary PPM next to the other test artifacts, to look at when a test fails.
void save_ppm(const Image& img, const std::string& name) {
    const std::string path = std::string(TUMBLE_TEST_ARTIFACTS) + "/" + name + ".ppm";
    if (std::FILE* f = std::fopen(path.c_str(), "wb")) {
        std::fprintf(f, "P6\n%d %d\n255\n", img.width, img.height);
        std::fwrite(img.rgb.data(), 1, img.rgb.size(), f);
        std::fclose(f);
    }
}

// A red unit sphere at (0,0,1) seen from 5 m away along +y, on a grey ground plane.
SceneView red_sphere_scene() {
    SceneView view;
    view.camera.position = {0.0f, -5.0f, 1.0f};
    view.camera.target = {0.0f, 0.0f, 1.0f};
    view.light.direction = {0.3f, 0.5f, -1.0f}; // from above, behind the camera's left shoulder
    view.instances.push_back({MeshKind::Plane,
                              glm::scale(glm::mat4(1.0f), glm::vec3(20.0f, 20.0f, 1.0f)),
                              {0.6f, 0.6f, 0.6f}});
    view.instances.push_back({MeshKind::Sphere,
                              glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, 1.0f)),
                              {0.9f, 0.1f, 0.1f}});
    return view;
}

TEST(Renderer, ContextIsOpenGl33OrNewer) {
    Renderer renderer({64, 48});
    const std::string version = renderer.gl_version();
    std::printf("GL_RENDERER = %s\nGL_VERSION  = %s\n", renderer.gl_renderer().c_str(),
                version.c_str());
    EXPECT_FALSE(renderer.gl_renderer().empty());
    ASSERT_FALSE(version.empty());
    const int major = version[0] - '0';
    const int minor = version.size() > 2 ? version[2] - '0' : 0;
    EXPECT_GE(major * 10 + minor, 33) << version;
}

TEST(Renderer, ImageSizeMatchesOptions) {
    Renderer renderer({320, 240});
    EXPECT_EQ(renderer.options().width, 320);
    EXPECT_EQ(renderer.options().height, 240);
    Image image(7, 3); // wrong size on purpose: draw must resize it
    renderer.draw(red_sphere_scene(), image);
    EXPECT_EQ(image.width, 320);
    EXPECT_EQ(image.height, 240);
    EXPECT_EQ(image.rgb.size(), 320u * 240u * 3u);
}

TEST(Renderer, SameSceneTwiceGivesIdenticalPixels) {
    Renderer renderer({160, 120});
    const SceneView scene = red_sphere_scene();
    SceneView other = scene;
    other.background = {0.1f, 0.1f, 0.1f};
    other.instances[1].color = {0.1f, 0.9f, 0.1f};
    Image first, second;
    renderer.draw(scene, first);
    renderer.draw(other, second); // a different frame in between must leave no trace
    renderer.draw(scene, second);
    EXPECT_TRUE(first.rgb == second.rgb);
}

TEST(Renderer, RedSphereIsCentredLitAndSurroundedByGroundAndSky) {
    Renderer renderer({160, 120});
    Image image;
    renderer.draw(red_sphere_scene(), image);
    save_ppm(image, "renderer_red_sphere");
    const Rgb centre = pixel(image, 80, 60);
    EXPECT_TRUE(reddish(centre)) << centre.r << " " << centre.g << " " << centre.b;
    // Lit from above: the upper part of the sphere is brighter than the lower part.
    EXPECT_GT(pixel(image, 80, 45).r, pixel(image, 80, 75).r + 30);
    // Far from the sphere: sky (bluish) in the top corner, grey ground in the bottom corner.
    const Rgb sky = pixel(image, 2, 2), ground = pixel(image, 2, 117);
    EXPECT_GT(sky.b, sky.r) << "sky " << sky.r << " " << sky.g << " " << sky.b;
    EXPECT_FALSE(reddish(ground));
    EXPECT_LT(std::abs(ground.r - ground.b), 20) << "ground should be grey";
}

// Rows are stored top-down: aiming the camera below the sphere puts it in the upper rows.
TEST(Renderer, ImageRowsAreTopDown) {
    SceneView scene = red_sphere_scene();
    scene.camera.target = {0.0f, 0.0f, -0.5f};
    Renderer renderer({160, 120});
    Image image;
    renderer.draw(scene, image);
    save_ppm(image, "renderer_top_down");
    long red_rows = 0, red_count = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            if (reddish(pixel(image, x, y))) red_rows += y, ++red_count;
        }
    }
    ASSERT_GT(red_count, 100);
    EXPECT_LT(red_rows / red_count, image.height / 2);
}

TEST(Renderer, EmptySceneIsSkyOnly) {
    Renderer renderer({32, 24});
    SceneView scene;
    Image image;
    renderer.draw(scene, image);
    // The sky gradient is paler at the horizon than overhead; looking slightly down, the whole
    // picture is near the background colour and never black.
    for (int y = 0; y < image.height; ++y) EXPECT_GT(pixel(image, 16, y).b, 150);
}

// Each Renderer owns its context; drawing with one between two draws of another changes nothing.
TEST(Renderer, TwoRenderersInOneThreadDoNotInterfere) {
    const SceneView scene = red_sphere_scene();
    Renderer a({96, 64});
    Image alone, interleaved, small;
    a.draw(scene, alone);
    {
        Renderer b({40, 30});
        b.draw(scene, small);
        a.draw(scene, interleaved);
        b.draw(scene, small);
    }
    a.draw(scene, interleaved); // after b is gone
    EXPECT_TRUE(alone.rgb == interleaved.rgb);
    EXPECT_EQ(small.width, 40);
}

TEST(Renderer, RejectsImpossibleImageSize) {
    EXPECT_THROW(Renderer({0, 240}), RenderError);
}

} // namespace
} // namespace tumble::render
