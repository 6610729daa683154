#include "cmd/dynamics_input.h"

#include "cmd/scene_command.h"

namespace quaternia {

void addMapFlags(CLI::App& command, MapFlags& flags, const std::string& formulaHelp,
                 const std::string& cHelp) {
    command.add_option(
        "--formula", flags.formula,
        formulaHelp + " (sets fractal.formula; default: the scene's fractal.formula)");
    command.add_option("--c", flags.c, cHelp + " (sets fractal.c; default: the scene's fractal.c)");
}

void applyMapFlags(Scene& scene, const MapFlags& flags) {
    if (flags.formula) setFromFlag(scene, "--formula", "fractal.formula", *flags.formula);
    if (flags.c)
        setFromFlag(scene, "--c", "fractal.c", quaternionValue(parseConstant(*flags.c, "--c")));
}

std::string formulaName(const MapFlags& flags) {
    return flags.formula ? "--formula" : "fractal.formula";
}

std::vector<double> quaternionValue(const Quaternion& q) {
    return {q.w, q.x, q.y, q.z};
}

}  // namespace quaternia
