// orbit and cycles: the reports of `quaternia orbit --json` and `quaternia cycles --json`, built
// by the same library functions (dynamics/orbit_report.h, cycles_report.h) and read by Python's
// json from the very text the CLI prints, so that the fields cannot differ.
#include "python/python_module.h"
#include "quaternia/dynamics/cycles_report.h"
#include "quaternia/dynamics/orbit_report.h"
#include "quaternia/scene/json.h"

namespace quaternia::python {
namespace {

// cyclesReport with the period named by its key.
CyclesReport cyclesOf(const Scene& scene, const std::string& formulaName) {
    return cyclesReport(scene, formulaName);
}

// The report `analyse` makes of the scene (computed without the GIL), as its --json text read
// by Python's json.
template <auto analyse>
py::object reportOf(const Scene& scene) {
    validateScene(scene);
    std::string text;
    {
        py::gil_scoped_release release;
        text = jsonText(toJson(analyse(scene, "fractal.formula")));
    }
    return py::module_::import("json").attr("loads")(text);
}

}  // namespace

void bindReports(py::module_& module) {
    module.def("_orbit", &reportOf<&orbitReport>, py::arg("scene"),
               "The `quaternia orbit --json` object of the scene, as a dict.");
    module.def("_cycles", &reportOf<&cyclesOf>, py::arg("scene"),
               "The `quaternia cycles --json` object of the scene, as a dict.");
}

}  // namespace quaternia::python
