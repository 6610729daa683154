#include "quaternia/scene/test_scenes.h"

#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_file.h"

namespace quaternia::testing {

std::string testDataPath(const std::string& relative) {
    return std::string(QUATERNIA_TEST_DATA_DIR) + "/" + relative;
}

Scene referenceScene(const std::string& id) {
    return loadScene(testDataPath("reference/" + id + ".toml"));
}

Scene unitBallScene(int width, int height) {
    Scene scene = defaultScene();
    scene.fractal.formula = "z^2 + c";
    scene.fractal.c = Quaternion{};
    scene.fractal.maxIterations = 30;
    scene.fractal.bailout = 0;
    scene.camera.position = {0, 0, -3};
    scene.camera.lookAt = {0, 0, 0};
    scene.render.width = width;
    scene.render.height = height;
    scene.render.samples = 1;
    return scene;
}

Scene darkUnitBallScene(int width, int height) {
    Scene scene = unitBallScene(width, height);
    scene.render.alpha = AlphaMode::Opaque;
    ShadingSettings& s = scene.shading;
    s.lightIntensity = 0;
    s.fillColor = {0, 0, 0};
    s.ambient = 0;
    s.ambientOcclusion = 0;
    s.specular = 0;
    s.coloring = Coloring::Solid;
    s.baseColor = {1, 1, 1};
    s.backgroundTop = s.backgroundBottom = {0, 0, 0};
    s.gamma = 1;
    s.exposure = 1;
    return scene;
}

}  // namespace quaternia::testing
