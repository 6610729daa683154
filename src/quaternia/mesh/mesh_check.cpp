#include "quaternia/mesh/mesh_check.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "quaternia/util/parallel.h"

namespace quaternia {
namespace {

// For each vertex, the triangles that use it (compressed rows: triangles of v are
// triangleIds[first[v] .. first[v + 1])).
struct VertexTriangles {
    std::vector<uint32_t> first, triangleIds;
};

VertexTriangles vertexTriangles(const Mesh& mesh) {
    VertexTriangles vt;
    vt.first.assign(mesh.positions.size() + 1, 0);
    for (const Triangle& t : mesh.triangles)
        for (uint32_t v : t)
            ++vt.first[v + 1];
    std::partial_sum(vt.first.begin(), vt.first.end(), vt.first.begin());
    vt.triangleIds.resize(vt.first.back());
    std::vector<uint32_t> fill(vt.first.begin(), vt.first.end() - 1);
    for (uint32_t k = 0; k < mesh.triangles.size(); ++k)
        for (uint32_t v : mesh.triangles[k])
            vt.triangleIds[fill[v]++] = k;
    return vt;
}

struct EdgeCounts {
    int64_t boundary = 0, nonManifold = 0, misoriented = 0, nonManifoldVertices = 0;
    EdgeCounts& operator+=(const EdgeCounts& o) {
        boundary += o.boundary, nonManifold += o.nonManifold, misoriented += o.misoriented;
        nonManifoldVertices += o.nonManifoldVertices;
        return *this;
    }
};

// Scratch of one worker, reused from vertex to vertex.
struct VertexScratch {
    std::vector<std::pair<uint32_t, int>> edges;      // (other end w > v, +1 for v->w, -1 for w->v)
    std::vector<std::pair<uint32_t, uint32_t>> link;  // (next, previous) of v in each triangle
};

// The edges {v, w} with w > v, each counted once (at its smaller end), and the fan around v.
void checkVertex(const Mesh& mesh, const VertexTriangles& vt, uint32_t v, VertexScratch& scratch,
                 EdgeCounts& counts) {
    scratch.edges.clear();
    scratch.link.clear();
    for (uint32_t i = vt.first[v]; i < vt.first[v + 1]; ++i) {
        const Triangle& t = mesh.triangles[vt.triangleIds[i]];
        int at = t[0] == v ? 0 : t[1] == v ? 1 : 2;
        uint32_t next = t[(at + 1) % 3], previous = t[(at + 2) % 3];
        if (next > v) scratch.edges.push_back({next, +1});
        if (previous > v) scratch.edges.push_back({previous, -1});
        scratch.link.push_back({next, previous});
    }
    std::sort(scratch.edges.begin(), scratch.edges.end());
    for (std::size_t i = 0; i < scratch.edges.size();) {
        std::size_t j = i;
        int forward = 0;
        for (; j < scratch.edges.size() && scratch.edges[j].first == scratch.edges[i].first; ++j)
            forward += scratch.edges[j].second > 0;
        std::size_t uses = j - i;
        if (uses == 1) ++counts.boundary;
        if (uses > 2) ++counts.nonManifold;
        if (uses == 2 && forward != 1) ++counts.misoriented;
        i = j;
    }
    // On a closed manifold the link of v is one cycle: next -> previous around the fan. Walk it
    // from the first triangle; a pinched vertex leaves triangles unvisited.
    auto& link = scratch.link;
    if (link.empty()) return;
    std::sort(link.begin(), link.end());
    uint32_t start = link[0].first, at = start;
    std::size_t visited = 0;
    do {
        auto it = std::lower_bound(link.begin(), link.end(), std::make_pair(at, uint32_t{0}));
        if (it == link.end() || it->first != at) return;  // open fan: an edge count reports it
        at = it->second;
        ++visited;
    } while (at != start && visited <= link.size());
    if (visited < link.size()) ++counts.nonManifoldVertices;
}

uint32_t findRoot(std::vector<uint32_t>& parent, uint32_t v) {
    while (parent[v] != v) {
        parent[v] = parent[parent[v]];  // path halving
        v = parent[v];
    }
    return v;
}

}  // namespace

MeshCheck checkMesh(const Mesh& mesh, int threads) {
    MeshCheck check;
    check.vertices = int64_t(mesh.positions.size());
    check.triangles = int64_t(mesh.triangles.size());
    EdgeCounts counts;
    {  // scoped: the table of triangles per vertex is as big as the triangles themselves
        VertexTriangles vt = vertexTriangles(mesh);
        ParallelOptions options;
        options.threads = threads;
        std::vector<EdgeCounts> perThread(std::size_t(resolveThreadCount(threads)));
        parallelFor(check.vertices, options, [&](int64_t begin, int64_t end, int thread) {
            VertexScratch scratch;
            for (int64_t v = begin; v < end; ++v)
                checkVertex(mesh, vt, uint32_t(v), scratch, perThread[std::size_t(thread)]);
        });
        for (const EdgeCounts& c : perThread)
            counts += c;
        for (std::size_t v = 0; v + 1 < vt.first.size(); ++v)
            check.unusedVertices += vt.first[v] == vt.first[v + 1];
    }
    check.boundaryEdges = counts.boundary;
    check.nonManifoldEdges = counts.nonManifold;
    check.misorientedEdges = counts.misoriented;
    check.nonManifoldVertices = counts.nonManifoldVertices;
    for (const Triangle& t : mesh.triangles) {
        bool repeated = t[0] == t[1] || t[1] == t[2] || t[0] == t[2];
        // Zero area as the float coordinates that files carry (and admesh reads) give it.
        Vector3f a = mesh.positions[t[0]];
        Vector3f n = cross(mesh.positions[t[1]] - a, mesh.positions[t[2]] - a);
        check.degenerateTriangles += repeated || dot(n, n) == 0.0f;
    }
    check.components = labelComponents(mesh).count;
    check.volume = signedVolume(mesh);
    check.area = surfaceArea(mesh);
    return check;
}

MeshComponents labelComponents(const Mesh& mesh) {
    std::vector<uint32_t> parent(mesh.positions.size());
    std::iota(parent.begin(), parent.end(), 0u);
    for (const Triangle& t : mesh.triangles) {
        uint32_t root = findRoot(parent, t[0]);
        for (int k = 1; k < 3; ++k) {
            uint32_t other = findRoot(parent, t[k]);
            if (other != root) parent[other] = root;
        }
    }
    constexpr uint32_t kNone = UINT32_MAX;
    std::vector<uint32_t> labelOfRoot(parent.size(), kNone);
    MeshComponents components;
    components.ofTriangle.reserve(mesh.triangles.size());
    for (const Triangle& t : mesh.triangles) {
        uint32_t& label = labelOfRoot[findRoot(parent, t[0])];
        if (label == kNone) label = components.count++;
        components.ofTriangle.push_back(label);
    }
    return components;
}

Mesh dropSmallComponents(const Mesh& mesh, double minimumVolume) {
    if (!(minimumVolume > 0)) return mesh;
    MeshComponents components = labelComponents(mesh);
    std::vector<double> volume(components.count, 0.0);
    for (std::size_t k = 0; k < mesh.triangles.size(); ++k)
        volume[components.ofTriangle[k]] += triangleSignedVolume(mesh, mesh.triangles[k]);
    std::vector<bool> keep(mesh.triangles.size());
    for (std::size_t k = 0; k < mesh.triangles.size(); ++k)
        keep[k] = std::abs(volume[components.ofTriangle[k]]) >= minimumVolume;
    return keepTriangles(mesh, keep);
}

}  // namespace quaternia
