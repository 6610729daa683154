// The Python extension module quaternia._quaternia; python/quaternia/__init__.py is the package
// around it (the image type, Mesh, reports as objects, show).
#include <hwy/targets.h>

#include "python/python_module.h"
#include "quaternia/render/lanes/march_lanes.h"
#include "quaternia/util/error.h"

PYBIND11_MODULE(_quaternia, module) {
    namespace python = quaternia::python;
    module.doc() = "Quaternia's library: scenes, renders, membership, meshes, orbits and planes.";
    python::bindErrors(module);
    python::bindScene(module);
    python::bindImages(module);
    python::bindPoints(module);
    python::bindMeshes(module);
    python::bindReports(module);
    module.def(
        "limit_isa",
        [](const std::string& name) {
            // Highway's better targets have the lower bits: a cap keeps the bits from its up.
            const std::pair<const char*, int64_t> caps[] = {
                {"best", 0}, {"avx3", HWY_AVX3}, {"avx2", HWY_AVX2}, {"sse4", HWY_SSE4}};
            for (const auto& [capName, target] : caps) {
                if (name != capName) continue;
                hwy::SetSupportedTargetsForTest(0);
                int64_t targets = hwy::SupportedTargets();
                if (target != 0) targets &= ~(target - 1);
                hwy::SetSupportedTargetsForTest(targets);
                hwy::GetChosenTarget().Update(hwy::SupportedTargets());
                return;
            }
            throw quaternia::UserError("isa",
                                       "isa must be best, avx3, avx2 or sse4, got '" + name + "'");
        },
        pybind11::arg("isa"),
        "Caps the lanes' instruction set (as `quaternia --isa`): \"best\", \"avx3\", \"avx2\" "
        "or \"sse4\", for benchmarks of a lesser machine's speed.");
    module.def("lane_target", &quaternia::laneTargetName,
               "The SIMD instruction set the lanes run on this CPU (e.g. \"AVX2\").");
}
