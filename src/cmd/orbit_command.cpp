#include "cmd/orbit_command.h"

#include <cstdio>

#include "cmd/dynamics_input.h"
#include "quaternia/dynamics/orbit_report.h"
#include "quaternia/scene/json.h"

namespace quaternia {
namespace {

Scene orbitScene(const OrbitCommandOptions& options) {
    Scene scene = sceneFromOptions(options);
    applyMapFlags(scene, options.map);
    if (options.z0)
        setFromFlag(scene, "--z0", "orbit.z0", quaternionValue(parseConstant(*options.z0, "--z0")));
    if (options.maxIterations)
        setFromFlag(scene, "--max-iterations", "orbit.max_iterations", *options.maxIterations);
    return scene;
}

}  // namespace

void addOrbitCommand(CLI::App& app, OrbitCommandOptions& options) {
    CLI::App* orbit = app.add_subcommand(
        "orbit",
        "The fate of one orbit of the scene's map (fractal.formula with fractal.c) from orbit.z0: "
        "escape, cycle (with multipliers and class) or undecided");
    addSceneInputOptions(*orbit, options);
    addMapFlags(*orbit, options.map, "The map, a polynomial in z and c",
                "The parameter c: a+bi, or a quaternion a+bi+cj+dk");
    orbit->add_option("--z0", options.z0,
                      "The starting point, complex or quaternion (sets orbit.z0; default 0)");
    orbit->add_option("--max-iterations", options.maxIterations,
                      "Iterations before giving up (sets orbit.max_iterations; default 1000)");
    orbit->add_flag("--json", options.json, "Print a machine-readable JSON report");
    orbit->footer(sceneHelpFooter());
}

int runOrbitCommand(const OrbitCommandOptions& options) {
    const OrbitReport report = orbitReport(orbitScene(options), formulaName(options.map));
    if (options.json) {
        std::printf("%s\n", jsonText(toJson(report)).c_str());
    } else {
        std::printf("%s", toText(report).c_str());
    }
    return 0;
}

}  // namespace quaternia
