#include "quaternia/mesh/mesh_io.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cstring>
#include <functional>
#include <vector>

#include "quaternia/util/error.h"

namespace quaternia {
namespace {

// Appends to a buffer and hands it to the sink (a file) a megabyte at a time, so that a mesh of
// tens of millions of triangles is never held twice in memory.
class BufferedWriter {
  public:
    using Sink = std::function<void(const uint8_t* data, std::size_t size)>;
    explicit BufferedWriter(Sink sink) : sink_(std::move(sink)) {
        buffer_.reserve(kFlushSize + 256);
    }

    void bytes(const void* data, std::size_t size) {
        const auto* p = static_cast<const uint8_t*>(data);
        buffer_.insert(buffer_.end(), p, p + size);
        if (buffer_.size() >= kFlushSize) flush();
    }
    void text(std::string_view s) { bytes(s.data(), s.size()); }
    // Little-endian whatever the host (the formats say so).
    void u32(uint32_t v) {
        uint8_t b[4] = {uint8_t(v), uint8_t(v >> 8), uint8_t(v >> 16), uint8_t(v >> 24)};
        bytes(b, 4);
    }
    void u16(uint16_t v) {
        uint8_t b[2] = {uint8_t(v), uint8_t(v >> 8)};
        bytes(b, 2);
    }
    void u8(uint8_t v) { bytes(&v, 1); }
    void f32(float v) { u32(std::bit_cast<uint32_t>(v)); }
    void vector(const Vector3f& v) {
        f32(v.x);
        f32(v.y);
        f32(v.z);
    }
    // Shortest text that reads back to the same float, then `separator`.
    void number(float v, char separator) {
        char digits[32];
        auto [end, error] = std::to_chars(digits, digits + sizeof digits, v);
        bytes(digits, std::size_t(end - digits));
        bytes(&separator, 1);
    }
    void integer(uint64_t v, char separator) {
        char digits[24];
        auto [end, error] = std::to_chars(digits, digits + sizeof digits, v);
        bytes(digits, std::size_t(end - digits));
        bytes(&separator, 1);
    }
    void flush() {
        sink_(buffer_.data(), buffer_.size());
        buffer_.clear();
    }

  private:
    static constexpr std::size_t kFlushSize = 1 << 20;
    Sink sink_;
    std::vector<uint8_t> buffer_;
};

void writeStl(const Mesh& mesh, BufferedWriter& out) {
    // The 80-byte header must not begin with "solid", which marks ASCII STL.
    char header[80];
    std::memset(header, 0, sizeof header);
    const char title[] = "binary STL from quaternia: a quaternion Julia set";
    std::memcpy(header, title, sizeof title - 1);
    out.bytes(header, sizeof header);
    out.u32(uint32_t(mesh.triangles.size()));
    for (const Triangle& t : mesh.triangles) {
        Vector3d n = triangleNormal(mesh, t);
        double len = length(n);
        out.vector(len > 0 ? Vector3f(n / len) : Vector3f());
        for (uint32_t v : t)
            out.vector(mesh.positions[v]);
        out.u16(0);  // attribute byte count
    }
}

void writePly(const Mesh& mesh, BufferedWriter& out) {
    bool normals = !mesh.normals.empty(), colors = !mesh.colors.empty();
    std::string header = "ply\nformat binary_little_endian 1.0\ncomment made by quaternia\n";
    header += "element vertex " + std::to_string(mesh.positions.size()) + "\n";
    header += "property float x\nproperty float y\nproperty float z\n";
    if (normals) header += "property float nx\nproperty float ny\nproperty float nz\n";
    if (colors) header += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
    header += "element face " + std::to_string(mesh.triangles.size()) + "\n";
    header += "property list uchar int vertex_indices\nend_header\n";
    out.text(header);
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        out.vector(mesh.positions[v]);
        if (normals) out.vector(mesh.normals[v]);
        if (colors) out.bytes(mesh.colors[v].data(), 3);
    }
    for (const Triangle& t : mesh.triangles) {
        out.u8(3);
        for (uint32_t v : t)
            out.u32(v);
    }
}

void writeObj(const Mesh& mesh, BufferedWriter& out) {
    bool normals = !mesh.normals.empty();
    out.text("# quaternia: a quaternion Julia set, " + std::to_string(mesh.positions.size()) +
             " vertices, " + std::to_string(mesh.triangles.size()) + " triangles\n");
    for (const Vector3f& p : mesh.positions) {
        out.text("v ");
        out.number(p.x, ' ');
        out.number(p.y, ' ');
        out.number(p.z, '\n');
    }
    if (normals) {
        for (const Vector3f& n : mesh.normals) {
            out.text("vn ");
            out.number(n.x, ' ');
            out.number(n.y, ' ');
            out.number(n.z, '\n');
        }
    }
    for (const Triangle& t : mesh.triangles) {
        out.text("f");
        for (int k = 0; k < 3; ++k) {
            out.text(" ");
            // OBJ counts from 1; "a//a" is vertex a with normal a.
            uint64_t index = uint64_t(t[k]) + 1;
            if (normals) {
                out.integer(index, '/');
                out.text("/");
            }
            out.integer(index, k == 2 ? '\n' : ' ');
        }
    }
}

}  // namespace

MeshFormat meshFormatFromPath(const std::string& path) {
    auto dot = path.find_last_of('.');
    auto slash = path.find_last_of('/');
    std::string extension;
    if (dot != std::string::npos && (slash == std::string::npos || dot > slash))
        extension = path.substr(dot + 1);
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char ch) { return char(std::tolower(ch)); });
    if (extension == "stl") return MeshFormat::Stl;
    if (extension == "ply") return MeshFormat::Ply;
    if (extension == "obj") return MeshFormat::Obj;
    throw UserError(path, "cannot tell the mesh format of '" + path +
                              "': the name must end in .stl, .ply or .obj");
}

const char* meshFormatName(MeshFormat format) {
    switch (format) {
        case MeshFormat::Stl:
            return "stl";
        case MeshFormat::Ply:
            return "ply";
        case MeshFormat::Obj:
        default:
            return "obj";
    }
}

static void writeMeshTo(const Mesh& mesh, MeshFormat format, BufferedWriter& out) {
    switch (format) {
        case MeshFormat::Stl:
            writeStl(mesh, out);
            break;
        case MeshFormat::Ply:
            writePly(mesh, out);
            break;
        case MeshFormat::Obj:
            writeObj(mesh, out);
            break;
    }
    out.flush();
}

void writeMesh(const Mesh& mesh, MeshFormat format, AtomicFile& file) {
    BufferedWriter out([&](const uint8_t* data, std::size_t size) { file.write(data, size); });
    writeMeshTo(mesh, format, out);
}

std::vector<uint8_t> encodeMesh(const Mesh& mesh, MeshFormat format) {
    std::vector<uint8_t> bytes;
    BufferedWriter out([&](const uint8_t* data, std::size_t size) {
        bytes.insert(bytes.end(), data, data + size);
    });
    writeMeshTo(mesh, format, out);
    return bytes;
}

}  // namespace quaternia
