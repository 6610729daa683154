// mesh and save_mesh: the mesher's surface as arrays, and the CLI's writers.
#include <cstring>

#include "python/python_module.h"
#include "quaternia/mesh/mesh_io.h"
#include "quaternia/mesh/mesher.h"
#include "quaternia/scene/scene_fractal.h"
#include "quaternia/util/atomic_file.h"
#include "quaternia/util/error.h"

namespace quaternia::python {
namespace {

py::dict meshArrays(const Scene& scene, std::optional<int64_t> resolution,
                    std::optional<int> threads, const py::object& progress,
                    const std::optional<std::string>& memoryBudget) {
    const Scene s = withOverrides(scene, {{"mesh.resolution", resolution}});
    validateScene(s);
    fractalFromScene(s);  // a bad formula is a ValueError before any work
    const int workers = threadsOf(threads);
    const MemoryBudget budget = memoryBudgetOf(memoryBudget, workers);
    MeshResult result = runWithoutGil(workers, progress, [&](const WorkOptions& work) {
        MeshOptions options{work};
        options.memory = budget;
        return meshScene(s, options);
    });
    Mesh& mesh = result.mesh;
    const py::ssize_t vertices = py::ssize_t(mesh.positions.size());
    const py::ssize_t faces = py::ssize_t(mesh.triangles.size());
    static_assert(sizeof(Vector3f) == 3 * sizeof(float) &&
                  sizeof(Triangle) == 3 * sizeof(uint32_t));
    py::dict arrays;
    arrays["vertices"] = adoptArray<float>(std::move(mesh.positions), {vertices, 3});
    arrays["faces"] = adoptArray<uint32_t>(std::move(mesh.triangles), {faces, 3});
    arrays["normals"] =
        adoptArray<float>(std::move(mesh.normals), {py::ssize_t(mesh.normals.size()), 3});
    arrays["colors"] =
        adoptArray<uint8_t>(std::move(mesh.colors), {py::ssize_t(mesh.colors.size()), 3});
    return arrays;
}

// The arrays (as meshArrays gives them, or any of the same shapes) written as the CLI writes.
void saveMesh(
    const std::string& path,
    const py::array_t<float, py::array::c_style | py::array::forcecast>& vertices,
    const py::array_t<int64_t, py::array::c_style | py::array::forcecast>& faces,
    const std::optional<py::array_t<float, py::array::c_style | py::array::forcecast>>& normals,
    const std::optional<py::array_t<uint8_t, py::array::c_style | py::array::forcecast>>& colors) {
    const MeshFormat format = meshFormatFromPath(path);
    if (vertices.ndim() != 2 || vertices.shape(1) != 3)
        throw UserError("vertices", "vertices must be an array (V, 3)");
    if (faces.ndim() != 2 || faces.shape(1) != 3)
        throw UserError("faces", "faces must be an array (F, 3)");
    Mesh mesh;
    const size_t count = size_t(vertices.shape(0));
    mesh.positions.resize(count);
    std::memcpy(static_cast<void*>(mesh.positions.data()), vertices.data(),
                count * sizeof(Vector3f));
    for (py::ssize_t f = 0; f < faces.shape(0); ++f) {
        Triangle t{};
        for (py::ssize_t k = 0; k < 3; ++k) {
            const int64_t v = faces.at(f, k);
            if (v < 0 || uint64_t(v) >= count)
                throw UserError("faces", "faces[" + std::to_string(f) + "] names vertex " +
                                             std::to_string(v) + " of " + std::to_string(count));
            t[size_t(k)] = uint32_t(v);
        }
        mesh.triangles.push_back(t);
    }
    if (normals && normals->size() > 0) {
        if (normals->ndim() != 2 || size_t(normals->shape(0)) != count || normals->shape(1) != 3)
            throw UserError("normals", "normals must be an array (V, 3)");
        mesh.normals.resize(count);
        std::memcpy(static_cast<void*>(mesh.normals.data()), normals->data(),
                    count * sizeof(Vector3f));
    }
    if (colors && colors->size() > 0) {
        if (colors->ndim() != 2 || size_t(colors->shape(0)) != count || colors->shape(1) != 3)
            throw UserError("colors", "colors must be an array (V, 3) of uint8");
        mesh.colors.resize(count);
        std::memcpy(mesh.colors.data(), colors->data(), count * sizeof(Rgb8));
    }
    try {
        AtomicFile file(path);
        writeMesh(mesh, format, file);
        file.commit();
    } catch (const UserError& error) {
        raiseOSError(error.what());  // the file could not be written
    }
}

}  // namespace

void bindMeshes(py::module_& module) {
    module.def("_mesh", &meshArrays, py::arg("scene"), py::arg("resolution") = py::none(),
               py::arg("threads") = py::none(), py::kw_only(), py::arg("progress") = py::none(),
               py::arg("memory_budget") = py::none());
    module.def("_save_mesh", &saveMesh, py::arg("path"), py::arg("vertices"), py::arg("faces"),
               py::arg("normals") = py::none(), py::arg("colors") = py::none());
}

}  // namespace quaternia::python
