#include "quaternia/mesh/mesh.h"

#include <cstddef>

namespace quaternia {
namespace {

Vector3d position(const Mesh& mesh, uint32_t vertex) {
    return Vector3d(mesh.positions[vertex]);
}

}  // namespace

Vector3d triangleNormal(const Mesh& mesh, const Triangle& t) {
    Vector3d a = position(mesh, t[0]);
    return cross(position(mesh, t[1]) - a, position(mesh, t[2]) - a);
}

double triangleSignedVolume(const Mesh& mesh, const Triangle& t) {
    return dot(position(mesh, t[0]), cross(position(mesh, t[1]), position(mesh, t[2]))) / 6;
}

double surfaceArea(const Mesh& mesh) {
    double area = 0;
    for (const Triangle& t : mesh.triangles)
        area += 0.5 * length(triangleNormal(mesh, t));
    return area;
}

double signedVolume(const Mesh& mesh) {
    double volume = 0;
    for (const Triangle& t : mesh.triangles)
        volume += triangleSignedVolume(mesh, t);
    return volume;
}

Mesh keepTriangles(const Mesh& mesh, const std::vector<bool>& keep) {
    constexpr uint32_t kUnused = UINT32_MAX;
    std::vector<uint32_t> newIndex(mesh.positions.size(), kUnused);
    Mesh out;
    for (std::size_t k = 0; k < mesh.triangles.size(); ++k)
        if (keep[k])
            for (uint32_t v : mesh.triangles[k])
                newIndex[v] = 0;
    for (std::size_t v = 0; v < newIndex.size(); ++v) {
        if (newIndex[v] == kUnused) continue;
        newIndex[v] = uint32_t(out.positions.size());
        out.positions.push_back(mesh.positions[v]);
        if (!mesh.normals.empty()) out.normals.push_back(mesh.normals[v]);
        if (!mesh.colors.empty()) out.colors.push_back(mesh.colors[v]);
    }
    for (std::size_t k = 0; k < mesh.triangles.size(); ++k) {
        if (!keep[k]) continue;
        const Triangle& t = mesh.triangles[k];
        out.triangles.push_back({newIndex[t[0]], newIndex[t[1]], newIndex[t[2]]});
    }
    return out;
}

}  // namespace quaternia
