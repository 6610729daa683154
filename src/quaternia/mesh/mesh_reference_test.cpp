// Meshes of the reference scenes (tests/data/reference): closed and manifold by their own
// check and by a real consumer, Debian's admesh; and in agreement with the renderer, whose
// ray-marched silhouette the mesh's silhouette matches.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "quaternia/image/mask_compare.h"
#include "quaternia/image/mask_test_helpers.h"
#include "quaternia/mesh/mesh_check.h"
#include "quaternia/mesh/mesh_io.h"
#include "quaternia/mesh/mesh_silhouette.h"
#include "quaternia/mesh/mesher.h"
#include "quaternia/render/render.h"
#include "quaternia/scene/test_scenes.h"
#include "quaternia/util/test_scratch_path.h"

namespace quaternia {
namespace {

namespace fs = std::filesystem;

const char* const kReferenceCases[] = {"case01_sqr_A", "case03_sqr_C", "case05_sqr_E",
                                       "case06_sqr_A_tilt", "case08_cube_F"};

MeshResult referenceMesh(const std::string& id, int resolution) {
    Scene scene = testing::referenceScene(id);
    scene.mesh.resolution = resolution;
    MeshOptions options;
    options.normalsAndColors = false;
    return meshScene(scene, options);
}

// admesh's report on an STL file, or empty if admesh cannot be run.
std::string admeshReport(const std::string& stlPath) {
    std::string command = "admesh '" + stlPath + "' 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    if (pipe == nullptr) return "";
    std::string report;
    char buffer[4096];
    while (std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe))
        report.append(buffer, n);
    return pclose(pipe) == 0 ? report : "";
}

// The first number after `label` (and a colon) in admesh's report; -1 if absent. Plain string
// scanning: std::regex trips GCC 12's -Wmaybe-uninitialized in optimised sanitizer builds.
double admeshValue(const std::string& report, const std::string& label) {
    for (std::size_t at = report.find(label); at != std::string::npos;
         at = report.find(label, at + 1)) {
        std::size_t colon = report.find_first_not_of(" \t", at + label.size());
        if (colon == std::string::npos || report[colon] != ':') continue;
        const char* start = report.c_str() + colon + 1;
        char* end = nullptr;
        double value = std::strtod(start, &end);
        if (end != start) return value;
    }
    return -1;
}

class MeshReference : public ::testing::TestWithParam<const char*> {};

TEST_P(MeshReference, ClosedManifoldAndAdmeshAgrees) {
    const std::string id = GetParam();
    MeshResult result = referenceMesh(id, 64);
    MeshCheck check = checkMesh(result.mesh);
    EXPECT_TRUE(check.watertight())
        << id << ": boundary " << check.boundaryEdges << ", non-manifold " << check.nonManifoldEdges
        << ", misoriented " << check.misorientedEdges << ", pinched " << check.nonManifoldVertices
        << ", degenerate " << check.degenerateTriangles;
    ASSERT_GT(check.triangles, 100);

    if (!fs::exists("/usr/bin/admesh") && std::system("command -v admesh >/dev/null") != 0)
        GTEST_SKIP() << "admesh is not installed (scripts/install-deps.sh installs it)";
    fs::path stl = testing::scratchPath(id + "_mesh.stl");
    {
        AtomicFile file(stl.string());
        writeMesh(result.mesh, MeshFormat::Stl, file);
        file.commit(false);
    }
    std::string report = admeshReport(stl.string());
    fs::remove(stl);
    ASSERT_FALSE(report.empty()) << "admesh failed";
    EXPECT_NE(report.find("No holes need to be filled"), std::string::npos) << report;
    EXPECT_EQ(admeshValue(report, "Total disconnected facets"), 0) << report;
    EXPECT_EQ(admeshValue(report, "Number of facets"), double(check.triangles));
    EXPECT_EQ(admeshValue(report, "Number of parts"), double(check.components)) << report;
    for (const char* fixed : {"Degenerate facets", "Edges fixed", "Facets removed", "Facets added",
                              "Facets reversed", "Backwards edges", "Normals fixed"})
        EXPECT_EQ(admeshValue(report, fixed), 0) << fixed << "\n" << report;
    // admesh sums in single precision.
    EXPECT_NEAR(admeshValue(report, "Volume"), check.volume, 1e-3 * check.volume) << report;
}

INSTANTIATE_TEST_SUITE_P(Cases, MeshReference, ::testing::ValuesIn(kReferenceCases));

// The mesh drawn through the reference camera covers the pixels the renderer hits.
TEST(MeshReferenceSilhouette, MatchesRayMarchedSilhouette) {
    Scene scene = testing::referenceScene("case01_sqr_A");
    scene.mesh.resolution = 256;
    MeshOptions options;
    options.normalsAndColors = false;
    MeshResult result = meshScene(scene, options);
    Mask rendered = maskFromAlpha(render(scene).image);
    Mask drawn = meshSilhouette(result.mesh, scene.camera, scene.render.width, scene.render.height);
    MaskComparison comparison = testing::compareNonEmptyMasks(drawn, rendered);
    EXPECT_GE(comparison.iou, 0.97) << describe(comparison);
    std::printf("mesh silhouette against ray marching: %s\n", describe(comparison).c_str());
    RecordProperty("iou", std::to_string(comparison.iou));
}

}  // namespace
}  // namespace quaternia
