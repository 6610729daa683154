// What the CLI tests compare the files they write with: the library's own result for the same
// scene. A file that merely starts with "PNG" could hold anything; one that decodes to the
// library's pixels and is byte for byte the library's encoding cannot pass by accident.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "quaternia/image/png_io.h"
#include "quaternia/mesh/mesh_io.h"
#include "quaternia/mesh/mesher.h"
#include "quaternia/plane/plane_render.h"
#include "quaternia/render/render_png.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene.h"

namespace quaternia::testing {

// The default scene at width x height with one sample per pixel (the CLI tests' kTiny).
inline Scene tinyScene(int64_t width, int64_t height) {
    Scene scene = defaultScene();
    setParameter(scene, "render.width", width);
    setParameter(scene, "render.height", height);
    setParameter(scene, "render.samples", int64_t(1));
    return scene;
}

// The file decodes to a non-empty image with the pixels of `libraryPng`, and is its bytes.
inline void expectPngIsLibrarys(const std::string& fileBytes,
                                const std::vector<uint8_t>& libraryPng) {
    ASSERT_FALSE(libraryPng.empty());
    const std::vector<uint8_t> bytes(fileBytes.begin(), fileBytes.end());
    const Image decoded = decodePng(bytes), expected = decodePng(libraryPng);
    EXPECT_GT(decoded.width() * decoded.height(), 0);
    EXPECT_EQ(decoded.width(), expected.width());
    EXPECT_EQ(decoded.height(), expected.height());
    EXPECT_TRUE(decoded.pixels() == expected.pixels()) << "the decoded pixels differ";
    EXPECT_TRUE(bytes == libraryPng) << "the file is not the library's encoding";
}

inline std::vector<uint8_t> libraryRenderPng(const Scene& scene) {
    RenderOptions options;
    return renderPng(scene, options).png;
}

inline std::vector<uint8_t> libraryDepthPng(const Scene& scene) {
    RenderOptions options;
    options.depth = true;
    return renderPng(scene, options).depthPng;
}

inline std::vector<uint8_t> libraryPlanePng(const Scene& scene) {
    return encodePng(renderPlane(scene).image, scene.render.bitDepth);
}

inline std::vector<uint8_t> libraryMesh(const Scene& scene, MeshFormat format) {
    return encodeMesh(meshScene(scene).mesh, format);
}

}  // namespace quaternia::testing
