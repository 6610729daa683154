// The writers read back: binary STL and PLY and text OBJ parsed here, independently of the
// writers, and compared with the mesh written.
#include "quaternia/mesh/mesh_io.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "quaternia/algebra/test_helpers.h"
#include "quaternia/util/test_scratch_path.h"

namespace quaternia {
namespace {

namespace fs = std::filesystem;

Mesh tetrahedron() {
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1.5f}};
    mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    for (const Vector3f& p : mesh.positions)
        mesh.normals.push_back(normalize(p - Vector3f(0.25f, 0.25f, 0.25f)));
    mesh.colors = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {10, 20, 30}};
    return mesh;
}

std::string written(const Mesh& mesh, const std::string& name) {
    fs::path path = testing::scratchPath(name);
    AtomicFile file(path.string());
    writeMesh(mesh, meshFormatFromPath(path.string()), file);
    file.commit(false);
    std::ifstream in(path, std::ios::binary);
    std::stringstream bytes;
    bytes << in.rdbuf();
    fs::remove(path);
    return bytes.str();
}

template <typename T>
T readAt(const std::string& bytes, std::size_t offset) {
    T value;
    std::memcpy(&value, bytes.data() + offset, sizeof value);  // the test host is little-endian
    return value;
}

TEST(MeshIo, FormatComesFromExtension) {
    EXPECT_EQ(meshFormatFromPath("a/b.stl"), MeshFormat::Stl);
    EXPECT_EQ(meshFormatFromPath("B.PLY"), MeshFormat::Ply);
    EXPECT_EQ(meshFormatFromPath("x.obj"), MeshFormat::Obj);
    UserError error = testing::thrownError([] { meshFormatFromPath("mesh.xyz"); });
    EXPECT_NE(std::string(error.what()).find(".stl, .ply or .obj"), std::string::npos);
    testing::thrownError([] { meshFormatFromPath("dir.stl/mesh"); });
}

TEST(MeshIo, BinaryStlReadsBack) {
    Mesh mesh = tetrahedron();
    std::string bytes = written(mesh, "t.stl");
    ASSERT_EQ(bytes.size(), 84u + 50u * 4u);
    EXPECT_NE(bytes.substr(0, 5), "solid");
    EXPECT_EQ(readAt<uint32_t>(bytes, 80), 4u);
    for (std::size_t k = 0; k < 4; ++k) {
        std::size_t at = 84 + 50 * k;
        Vector3d n = normalize(triangleNormal(mesh, mesh.triangles[k]));
        EXPECT_NEAR(readAt<float>(bytes, at), n.x, 1e-6);
        EXPECT_NEAR(readAt<float>(bytes, at + 8), n.z, 1e-6);
        for (int corner = 0; corner < 3; ++corner) {
            const Vector3f& p = mesh.positions[mesh.triangles[k][std::size_t(corner)]];
            EXPECT_EQ(readAt<float>(bytes, at + 12 + 12 * std::size_t(corner)), p.x);
            EXPECT_EQ(readAt<float>(bytes, at + 20 + 12 * std::size_t(corner)), p.z);
        }
    }
}

TEST(MeshIo, BinaryPlyReadsBack) {
    Mesh mesh = tetrahedron();
    std::string bytes = written(mesh, "t.ply");
    std::size_t body = bytes.find("end_header\n");
    ASSERT_NE(body, std::string::npos);
    std::string header = bytes.substr(0, body);
    body += 11;
    for (const char* line :
         {"format binary_little_endian 1.0", "element vertex 4", "property float nx",
          "property uchar red", "element face 4", "property list uchar int vertex_indices"})
        EXPECT_NE(header.find(line), std::string::npos) << line;
    ASSERT_EQ(bytes.size(), body + 4 * 27 + 4 * 13);
    for (std::size_t v = 0; v < 4; ++v) {
        std::size_t at = body + 27 * v;
        EXPECT_EQ(readAt<float>(bytes, at + 8), mesh.positions[v].z);
        EXPECT_EQ(readAt<float>(bytes, at + 12), mesh.normals[v].x);
        EXPECT_EQ(uint8_t(bytes[at + 26]), mesh.colors[v][2]);
    }
    for (std::size_t k = 0; k < 4; ++k) {
        std::size_t at = body + 4 * 27 + 13 * k;
        EXPECT_EQ(bytes[at], 3);
        for (std::size_t c = 0; c < 3; ++c)
            EXPECT_EQ(readAt<int32_t>(bytes, at + 1 + 4 * c), int32_t(mesh.triangles[k][c]));
    }
}

TEST(MeshIo, ObjReadsBack) {
    Mesh mesh = tetrahedron();
    std::istringstream text(written(mesh, "t.obj"));
    std::vector<Vector3f> positions, normals;
    std::vector<Triangle> triangles;
    for (std::string line; std::getline(text, line);) {
        std::istringstream in(line);
        std::string tag;
        in >> tag;
        if (tag == "v" || tag == "vn") {
            Vector3f p;
            in >> p.x >> p.y >> p.z;
            (tag == "v" ? positions : normals).push_back(p);
        } else if (tag == "f") {
            Triangle t;
            for (uint32_t& v : t) {
                std::string corner;
                in >> corner;  // a//a
                auto slash = corner.find("//");
                ASSERT_NE(slash, std::string::npos);
                EXPECT_EQ(corner.substr(0, slash), corner.substr(slash + 2));
                v = uint32_t(std::stoul(corner)) - 1;
            }
            triangles.push_back(t);
        }
    }
    ASSERT_EQ(positions.size(), 4u);
    for (std::size_t v = 0; v < 4; ++v) {
        EXPECT_EQ(positions[v], mesh.positions[v]);
        EXPECT_EQ(normals[v], mesh.normals[v]);
    }
    EXPECT_EQ(triangles, mesh.triangles);
}

}  // namespace
}  // namespace quaternia
