#include "cmd/cycles_command.h"

#include <cmath>
#include <cstdio>
#include <vector>

#include "cmd/dynamics_input.h"
#include "quaternia/algebra/complex_polynomial.h"
#include "quaternia/dynamics/periodic_points.h"
#include "quaternia/scene/json.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

ComplexRestriction complexMap(const Scene& scene, const std::string& formula) {
    Polynomial p = compileMap(scene.fractal.formula, scene.fractal.c, formula);
    std::optional<ComplexRestriction> restriction = restrictToComplexPlane(p);
    if (!restriction) {
        throw UserError(formula,
                        formula + ": cycles needs a complex polynomial, but the coefficients of " +
                            p.toString() + " do not lie in one plane C_u = span{1, u}");
    }
    return *restriction;
}

// The table bounds the period for degree 2; higher degrees allow less. `name` is --period or
// cycles.period, whichever set it.
void checkPeriod(int period, int degree, const std::string& name) {
    if (period < 1 ||
        period * std::log(double(degree)) > std::log(double(kMaxPeriodicPoints)) + 1e-9) {
        throw UserError(name, name + " must be at least 1 with degree^period <= " +
                                  std::to_string(kMaxPeriodicPoints) + " (degree " +
                                  std::to_string(degree) + "), got " + std::to_string(period));
    }
}

std::string cycleNote(const PeriodicCycle& cycle) {
    std::vector<std::string> notes;
    if (cycle.degenerate) notes.push_back("collapsed onto period " + std::to_string(cycle.period));
    if (cycle.multiplicity > 1)
        notes.push_back("multiplicity " + std::to_string(cycle.multiplicity));
    if (!cycle.complete) notes.push_back("incomplete: an image matched no root");
    if (cycle.classification.unsure) notes.push_back("class unsure");
    std::string text;
    for (const std::string& note : notes)
        text += (text.empty() ? " (" : "; ") + note;
    return text.empty() ? text : text + ")";
}

void printTable(const Scene& scene, const ComplexRestriction& map, const PeriodicPoints& points) {
    std::printf("%s with c = %s: %lld point%s of period %d in %zu cycle%s\n",
                scene.fractal.formula.c_str(), formatQuaternion(scene.fractal.c).c_str(),
                static_cast<long long>(points.count), points.count == 1 ? "" : "s", points.period,
                points.cycles.size(), points.cycles.size() == 1 ? "" : "s");
    if (norm(map.axis - kUnitI) > 1e-12) {
        std::printf("(complex numbers x+yi stand for x + y u in the plane C_u, u = %s)\n",
                    formatQuaternion(map.axis).c_str());
    }
    std::printf("%4s  %-28s %-13s %-16s %s\n", "#", "multiplier", "|multiplier|", "class",
                "points");
    for (std::size_t i = 0; i < points.cycles.size(); ++i) {
        const PeriodicCycle& cycle = points.cycles[i];
        std::string list;
        for (std::complex<double> z : cycle.points)
            list += (list.empty() ? "" : " -> ") + formatComplex(z);
        std::printf("%4zu  %-28s %-13s %-16s %s%s\n", i + 1,
                    formatComplex(cycle.multiplier).c_str(),
                    formatComplex(std::abs(cycle.multiplier)).c_str(),
                    toString(cycle.classification.stability).c_str(), list.c_str(),
                    cycleNote(cycle).c_str());
    }
}

void printJson(const Scene& scene, const ComplexRestriction& map, const PeriodicPoints& points) {
    Json json;
    json["command"] = "cycles";
    json["formula"] = scene.fractal.formula;
    json["c"] = scene.fractal.c;
    json["plane_axis"] = map.axis;
    json["period"] = points.period;
    json["points"] = points.count;
    json["cycles"] = Json::array();
    for (const PeriodicCycle& cycle : points.cycles) {
        Json entry;
        entry["period"] = cycle.period;
        entry["points"] = cycle.points;
        entry["multiplier"] = cycle.multiplier;
        entry["class"] = toString(cycle.classification.stability);
        entry["unsure"] = cycle.classification.unsure;
        entry["degenerate"] = cycle.degenerate;
        entry["multiplicity"] = cycle.multiplicity;
        entry["complete"] = cycle.complete;
        entry["residual"] = cycle.residual;
        json["cycles"].push_back(std::move(entry));
    }
    std::printf("%s\n", jsonText(json).c_str());
}

}  // namespace

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
    requireQuaternionAlgebra(scene, "cycles");
    if (options.period) setFromFlag(scene, "--period", "cycles.period", *options.period);
    ComplexRestriction map = complexMap(scene, formulaName(options.map));
    checkPeriod(scene.cycles.period, map.polynomial.degree(),
                options.period ? "--period" : "cycles.period");
    PeriodicPoints points = periodicPoints(map.polynomial, scene.cycles.period);
    if (options.json) {
        printJson(scene, map, points);
    } else {
        printTable(scene, map, points);
    }
    return 0;
}

}  // namespace quaternia
