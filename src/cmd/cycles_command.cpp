#include "cmd/cycles_command.h"

#include <cstdio>

#include "cmd/dynamics_input.h"
#include "quaternia/dynamics/cycles_report.h"
#include "quaternia/scene/json.h"
#include "quaternia/scene/scene_fractal.h"

namespace quaternia {

void addCyclesCommand(CLI::App& app, CyclesCommandOptions& options) {
    CLI::App* cycles = app.add_subcommand(
        "cycles",
        "All periodic points of one period (cycles.period) of the scene's map, a complex "
        "polynomial, as cycles");
    addSceneInputOptions(*cycles, options);
    addMapFlags(*cycles, options.map,
                "The map, a polynomial in z and c whose coefficients share a plane C_u",
                "The parameter c: a+bi (or a quaternion in one plane)");
    cycles->add_option("--period", options.period,
                       "The period n, degree^n <= " + std::to_string(kMaxPeriodicPoints) +
                           " (sets cycles.period; default 1)");
    cycles->add_flag("--json", options.json, "Print JSON instead of a table");
    cycles->footer(sceneHelpFooter());
}

int runCyclesCommand(const CyclesCommandOptions& options) {
    Scene scene = sceneFromOptions(options);
    applyMapFlags(scene, options.map);
    // Before --period is applied, so that a scene in another algebra is refused whatever the
    // period (cyclesReport checks it too, for the front ends that call it alone).
    requireQuaternionAlgebra(scene, "cycles");
    if (options.period) setFromFlag(scene, "--period", "cycles.period", *options.period);
    const CyclesReport report = cyclesReport(scene, formulaName(options.map),
                                             options.period ? "--period" : "cycles.period");
    if (options.json) {
        std::printf("%s\n", jsonText(toJson(report)).c_str());
    } else {
        std::printf("%s", toText(report).c_str());
    }
    return 0;
}

}  // namespace quaternia
