// The Python extension module quaternia._quaternia; python/quaternia/__init__.py is the package
// around it (the image type, Mesh, reports as objects, show).
#include "python/python_module.h"
#include "quaternia/render/lanes/march_lanes.h"

PYBIND11_MODULE(_quaternia, module) {
    namespace python = quaternia::python;
    module.doc() = "Quaternia's library: scenes, renders, membership, meshes, orbits and planes.";
    python::bindErrors(module);
    python::bindScene(module);
    python::bindImages(module);
    python::bindPoints(module);
    python::bindMeshes(module);
    python::bindReports(module);
    module.def("lane_target", &quaternia::laneTargetName,
               "The SIMD instruction set the lanes run on this CPU (e.g. \"AVX2\").");
}
