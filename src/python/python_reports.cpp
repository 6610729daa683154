// orbit and cycles: the reports of `quaternia orbit --json` and `quaternia cycles --json`, built
// by the same library functions (dynamics/orbit_report.h, cycles_report.h) and read by Python's
// json from the very text the CLI prints, so that the fields cannot differ.
#include "python/python_module.h"
#include "quaternia/dynamics/cycles_report.h"
#include "quaternia/dynamics/orbit_report.h"
#include "quaternia/scene/json.h"

namespace quaternia::python {
namespace {

py::object pythonOf(const Json& json) {
    const std::string text = jsonText(json);
    return py::module_::import("json").attr("loads")(text);
}

}  // namespace

void bindReports(py::module_& module) {
    module.def(
        "_orbit",
        [](const Scene& scene) {
            validateScene(scene);
            Json json;
            {
                py::gil_scoped_release release;
                json = toJson(orbitReport(scene));
            }
            return pythonOf(json);
        },
        py::arg("scene"), "The `quaternia orbit --json` object of the scene, as a dict.");
    module.def(
        "_cycles",
        [](const Scene& scene) {
            validateScene(scene);
            Json json;
            {
                py::gil_scoped_release release;
                json = toJson(cyclesReport(scene));
            }
            return pythonOf(json);
        },
        py::arg("scene"), "The `quaternia cycles --json` object of the scene, as a dict.");
}

}  // namespace quaternia::python
