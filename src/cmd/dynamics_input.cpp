#include "cmd/dynamics_input.h"

#include <algorithm>

#include "cmd/scene_command.h"
#include "quaternia/algebra/formula.h"
#include "quaternia/util/error.h"

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

Hypercomplex cOfScene(const Scene& scene) {
    const Quaternion& c = scene.fractal.c;
    const std::array<double, 4>& upper = scene.fractal.cUpper;
    Hypercomplex value{c.w, c.x, c.y, c.z, 0, 0, 0, 0};
    if (algebraDimension(scene.fractal.algebra) == 8)
        std::copy(upper.begin(), upper.end(), value.begin() + 4);
    return value;
}

std::vector<double> cComponents(const Scene& scene) {
    const Hypercomplex c = cOfScene(scene);
    return {c.begin(), c.begin() + algebraDimension(scene.fractal.algebra)};
}

void requireQuaternionAlgebra(const Scene& scene, const std::string& command) {
    if (scene.fractal.algebra == Algebra::kQuaternion) return;
    throw UserError("fractal.algebra",
                    "fractal.algebra = \"" + std::string(algebraName(scene.fractal.algebra)) +
                        "\": `quaternia " + command +
                        "` works in the quaternions only so far; render, mesh, orbit and "
                        "plane (plane.kind = \"slice\") take every algebra");
}

Polynomial compileMap(const std::string& formula, const Quaternion& c, const std::string& name) {
    Polynomial p = compileFormula(formula, c, name);
    try {
        p.escapeRadius();
    } catch (const UserError& e) {
        // The library names the scene key; the formula may have come from --formula.
        std::string message = e.what();
        const std::string key = "fractal.formula";
        if (message.starts_with(key)) message = name + message.substr(key.size());
        throw UserError(name, message);
    }
    return p;
}

}  // namespace quaternia
