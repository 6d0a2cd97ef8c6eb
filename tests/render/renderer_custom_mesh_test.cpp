// Cylinders and custom triangle meshes (MeshKind::Cylinder, MeshKind::Custom + SceneView::meshes)
// are drawn where their transforms put them, and custom meshes are uploaded once per MeshData.
#include "render/mesh.h"
#include "render/renderer.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <memory>

namespace tumble::render {
namespace {

// Pixels whose colour is clearly the given primary (0 = red, 1 = green, 2 = blue): the sky
// and grey ground never are, a lit (highlights and reflections included) coloured body is.
int count_primary(const Image& img, int channel) {
    int n = 0;
    for (std::size_t i = 0; i < img.rgb.size(); i += 3) {
        const int c = img.rgb[i + std::size_t(channel)];
        const int o1 = img.rgb[i + std::size_t((channel + 1) % 3)];
        const int o2 = img.rgb[i + std::size_t((channel + 2) % 3)];
        n += c > 90 && c > o1 + 60 && c > o2 + 60;
    }
    return n;
}

SceneView camera_on_origin() {
    SceneView view;
    view.camera.position = {0.0f, -6.0f, 0.0f};
    view.camera.target = {0.0f, 0.0f, 0.0f};
    view.light.direction = {0.3f, 0.8f, -0.6f};
    return view;
}

std::shared_ptr<const MeshData> tetrahedron() {
    const std::vector<glm::vec3> p{{-1, -1, -1}, {1, -1, -1}, {0, 1, -1}, {0, 0, 1}};
    return std::make_shared<const MeshData>(
        flat_shaded_mesh(p, {0, 2, 1, 0, 1, 3, 1, 2, 3, 2, 0, 3}));
}

TEST(RendererCustomMesh, CylinderIsDrawnWhereItsTransformPutsIt) {
    Renderer renderer({120, 90});
    SceneView view = camera_on_origin();
    // Lying along x, 2 m long: wider than tall on screen.
    const glm::mat4 m = glm::scale(glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), {0, 1, 0}),
                                   glm::vec3(0.3f, 0.3f, 1.0f));
    view.instances.push_back({MeshKind::Cylinder, m, {0.9f, 0.1f, 0.1f}});
    Image image;
    renderer.draw(view, image);
    int min_x = 1000, max_x = -1, min_y = 1000, max_y = -1;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* p = image.row(y) + 3 * x;
            if (p[0] > 90 && p[0] > 2 * p[1]) {
                min_x = std::min(min_x, x), max_x = std::max(max_x, x);
                min_y = std::min(min_y, y), max_y = std::max(max_y, y);
            }
        }
    ASSERT_GE(max_x, 0) << "no cylinder drawn";
    EXPECT_GT(max_x - min_x, 3 * (max_y - min_y));
    EXPECT_NEAR((min_x + max_x) / 2.0, 60.0, 2.0); // centred
}

TEST(RendererCustomMesh, CustomMeshIsDrawnAndUnknownIdsAreAnError) {
    Renderer renderer({120, 90});
    SceneView view = camera_on_origin();
    view.meshes.push_back(tetrahedron());
    view.instances.push_back({MeshKind::Custom, glm::mat4(1.0f), {0.1f, 0.8f, 0.1f}, 0});
    Image image;
    renderer.draw(view, image);
    EXPECT_GT(count_primary(image, 1), 500);
    view.instances[0].mesh_id = 1;
    EXPECT_THROW(renderer.draw(view, image), RenderError);
}

// Two meshes in one view are told apart by mesh_id; a new MeshData after the old one is freed
// is uploaded afresh even if it happens to live at the same address.
TEST(RendererCustomMesh, MeshIdsSelectMeshesAndReplacedMeshesAreReuploaded) {
    Renderer renderer({120, 90});
    SceneView view = camera_on_origin();
    view.meshes = {tetrahedron(), std::make_shared<const MeshData>(make_box())};
    view.instances.push_back(
        {MeshKind::Custom, glm::scale(glm::mat4(1.0f), glm::vec3(0.5f)), {0.1f, 0.1f, 0.9f}, 1});
    Image box, tet, again;
    renderer.draw(view, box);
    view.instances[0].mesh_id = 0;
    renderer.draw(view, tet);
    EXPECT_GT(count_primary(box, 2), count_primary(tet, 2) + 100); // a 1 m square vs a triangle
    for (int i = 0; i < 3; ++i) { // replace mesh 0 by fresh box copies
        view.meshes[0] = std::make_shared<const MeshData>(make_box());
        renderer.draw(view, again);
        EXPECT_EQ(again.rgb, box.rgb) << "round " << i;
    }
}

} // namespace
} // namespace tumble::render
