// `quaternia mesh` as a user meets it: each format written with a summary, JSON, and bad input
// refused in one line with exit code 2 and no file left behind.
#include "cmd/cli_fixture.h"
#include "cmd/cli_library_results.h"
#include "quaternia/scene/json.h"

namespace quaternia {
namespace {

using MeshCli = testing::CliFixture;
using testing::CommandResult;
using testing::readFile;
namespace fs = std::filesystem;

const std::string kSmall = " --resolution 24 --threads 2";

TEST_F(MeshCli, MeshWritesEachFormatWithSummary) {
    for (const char* name : {"out.stl", "out.ply", "out.obj"}) {
        CommandResult r = run("mesh -o " + output(name) + kSmall);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        EXPECT_NE(r.out.find("closed"), std::string::npos) << r.out;
        EXPECT_NE(r.out.find("triangles"), std::string::npos) << r.out;
        EXPECT_TRUE(r.err.empty()) << r.err;
        ASSERT_TRUE(fs::exists(output(name))) << name;
    }
    // Each file is the library's mesh of the scene in that format.
    Scene scene = defaultScene();
    setParameter(scene, "mesh.resolution", int64_t(24));
    const Mesh mesh = meshScene(scene).mesh;
    ASSERT_GT(mesh.triangles.size(), 1000u);
    for (const char* name : {"out.stl", "out.ply", "out.obj"}) {
        const std::vector<uint8_t> expected = encodeMesh(mesh, meshFormatFromPath(name));
        EXPECT_TRUE(readFile(output(name)) == std::string(expected.begin(), expected.end()))
            << name;
    }
    EXPECT_EQ(readFile(output("out.ply")).substr(0, 4), "ply\n");
}

TEST_F(MeshCli, MeshPrintsJsonSummary) {
    fs::path scene = write("ball.toml", "[fractal]\nc = [0, 0, 0, 0]\n[mesh]\niso = 0.5\n");
    CommandResult r = run("mesh " + scene.string() + " --json -o " + output("b.stl") + kSmall +
                          " --min-component 0.001");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    Json summary = Json::parse(r.out);
    EXPECT_EQ(summary["resolution"], 24) << r.out;
    EXPECT_EQ(summary["iso"], 0.5) << r.out;
    EXPECT_EQ(summary["min_component"], 0.001) << r.out;
    EXPECT_EQ(summary["watertight"], true) << r.out;
    EXPECT_EQ(summary["components"], 1) << r.out;
    for (const char* key : {"volume", "area", "triangles", "seconds"})
        EXPECT_TRUE(summary[key].is_number()) << key << " in " << r.out;
}

TEST_F(MeshCli, MeshRefusesBadInput) {
    expectUserError(run("mesh -o " + output("m.stl") + " --resolution 0"), "mesh.resolution");
    expectUserError(run("mesh -o " + output("m.stl") + " --resolution 5000"), "mesh.resolution");
    expectUserError(run("mesh -o " + output("m.xyz") + kSmall), ".stl, .ply or .obj");
    expectUserError(run("mesh -o " + (dir_ / "missing" / "m.stl").string() + kSmall),
                    "cannot write");
    expectUserError(run("mesh -o " + output("m.stl") + " --iso -1"), "mesh.iso");
}

}  // namespace
}  // namespace quaternia
