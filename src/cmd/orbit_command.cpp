#include "cmd/orbit_command.h"

#include <cstdio>
#include <variant>

#include "cmd/dynamics_input.h"
#include "quaternia/algebra/formula.h"
#include "quaternia/dynamics/connectedness.h"
#include "quaternia/dynamics/orbit.h"
#include "quaternia/fractal/hypercomplex_julia.h"
#include "quaternia/scene/json.h"
#include "quaternia/scene/scene_fractal.h"
#include "quaternia/util/error.h"
#include "quaternia/util/number_format.h"

namespace quaternia {
namespace {

std::string classText(const Classification& c) {
    return toString(c.stability) + (c.unsure ? " (unsure)" : "");
}

// Points and c as text and JSON: quaternions (and the 4-component algebras) as a+bi+cj+dk,
// the 8-component algebras as their list of components, as the scene file writes them.
std::string pointText(const Scene&, const Quaternion& q) {
    return formatQuaternion(q);
}

std::string pointText(const Scene& scene, const Hypercomplex& q) {
    const int dimension = algebraDimension(scene.fractal.algebra);
    if (dimension == 4) return formatQuaternion(Quaternion(q[0], q[1], q[2], q[3]));
    std::string text = "[";
    for (int n = 0; n < dimension; ++n)
        text += (n ? ", " : "") + roundedNumber(q[size_t(n)], kReportDigits);
    return text + "]";
}

Json pointJson(const Scene&, const Quaternion& q) {
    return q;
}

Json pointJson(const Scene& scene, const Hypercomplex& q) {
    return std::vector<double>(q.begin(), q.begin() + algebraDimension(scene.fractal.algebra));
}

// "H" for the quaternions, else the algebra's name and the Jacobian's size.
std::string algebraLabel(const Scene& scene) {
    if (scene.fractal.algebra == Algebra::kQuaternion) return "H";
    const int n = algebraDimension(scene.fractal.algebra);
    return std::string(algebraName(scene.fractal.algebra)) + " (" + std::to_string(n) + "x" +
           std::to_string(n) + ")";
}

template <typename Result>
std::string fateText(const Result& r) {
    int period = r.cycle ? r.cycle->period() : 0;
    std::string cycle = std::to_string(period) + "-cycle";
    switch (r.fate) {
        case OrbitFate::Escapes:
            return "escapes at iteration " + std::to_string(r.escapeIteration) +
                   " (|z| > escape radius " + roundedNumber(r.escapeRadius, kReportDigits) + ")";
        case OrbitFate::Periodic:
            return period == 1 ? "fixed point" : "periodic with period " + std::to_string(period);
        case OrbitFate::Preperiodic:
            return "strictly preperiodic with preperiod " + std::to_string(r.preperiod) +
                   " and period " + std::to_string(period);
        case OrbitFate::Attracted:
            return "attracted to a " + cycle + " (within " +
                   roundedNumber(r.tolerance, kReportDigits) + " of it from iteration " +
                   std::to_string(r.preperiod) + ")";
        case OrbitFate::Undecided:
            return "undecided after " + std::to_string(r.iterations) + " iterations";
    }
    return "";
}

std::string connectednessText(const Connectedness& k) {
    std::string text = k.connected ? "connected" : k.cantor ? "a Cantor set" : "disconnected";
    text += " (critical orbit";
    text += k.criticalOrbits.size() == 1 ? " " : "s ";
    for (std::size_t i = 0; i < k.criticalOrbits.size(); ++i) {
        const CriticalOrbit& critical = k.criticalOrbits[i];
        text +=
            (i ? ", " : "") + formatComplex(critical.point) + ": " + toString(critical.orbit.fate);
    }
    return text + ")" + (k.certain ? "" : ", not certain: an orbit stayed undecided");
}

template <typename Result>
void printText(const Scene& scene, const Result& r, const std::optional<Connectedness>& k) {
    const std::string algebra =
        scene.fractal.algebra == Algebra::kQuaternion
            ? ""
            : " in the " + std::string(algebraName(scene.fractal.algebra)) + " algebra";
    std::printf("orbit of z0 = %s under %s%s, c = %s\n", formatQuaternion(scene.orbit.z0).c_str(),
                scene.fractal.formula.c_str(), algebra.c_str(),
                pointText(scene, cOfScene(scene)).c_str());
    std::printf("fate: %s\n", fateText(r).c_str());
    if (r.cycle) {
        const auto& cycle = *r.cycle;
        std::string points;
        for (const auto& w : cycle.points)
            points += (points.empty() ? "" : " -> ") + pointText(scene, w);
        std::printf("cycle: %s\n", points.c_str());
        if (cycle.multiplier) {
            std::printf("multiplier: %s (|lambda| = %s), %s\n",
                        formatComplex(*cycle.multiplier).c_str(),
                        formatComplex(std::abs(*cycle.multiplier)).c_str(),
                        classText(cycle.complexClass).c_str());
        }
        std::string eigen;
        for (std::complex<double> e : cycle.eigenvalues)
            eigen += (eigen.empty() ? "" : ", ") + formatComplex(e);
        std::printf("in %s: Jacobian eigenvalues %s, %s\n", algebraLabel(scene).c_str(),
                    eigen.c_str(), classText(cycle.classInH).c_str());
    }
    if (r.unsure) std::printf("unsure: %s\n", r.note.empty() ? "see the class" : r.note.c_str());
    if (k) std::printf("K: %s\n", connectednessText(*k).c_str());
}

template <typename Cycle>
Json jsonCycle(const Scene& scene, const Cycle& cycle) {
    Json json;
    json["period"] = cycle.period();
    json["points"] = Json::array();
    for (const auto& w : cycle.points)
        json["points"].push_back(pointJson(scene, w));
    json["multiplier"] = cycle.multiplier ? Json(*cycle.multiplier) : Json();
    json["plane_axis"] = cycle.multiplier ? Json(cycle.axis) : Json();
    json["class"] = cycle.multiplier ? Json(toString(cycle.complexClass.stability)) : Json();
    json["class_in_h"] = toString(cycle.classInH.stability);
    json["eigenvalues"] = cycle.eigenvalues;
    json["jacobian"] = cycle.jacobian;
    json["residual"] = cycle.residual;
    json["refined"] = cycle.refined;
    return json;
}

// The fields an orbit's report shares with each critical orbit's, added to `json`.
template <typename Result>
void addOrbit(Json& json, const Result& r) {
    json["fate"] = toString(r.fate);
    json["escape_iteration"] = r.fate == OrbitFate::Escapes ? Json(r.escapeIteration) : Json();
    json["preperiod"] = r.preperiod;
    json["period"] = r.cycle ? Json(r.cycle->period()) : Json();
    json["class"] = r.cycle ? Json(toString(r.governingClass.stability)) : Json();
    json["unsure"] = r.unsure;
    json["note"] = r.note;
}

Json jsonConnectedness(const Connectedness& k) {
    Json json;
    json["connected"] = k.connected;
    json["cantor"] = k.cantor;
    json["certain"] = k.certain;
    json["critical_orbits"] = Json::array();
    for (const CriticalOrbit& critical : k.criticalOrbits) {
        Json orbit;
        orbit["point"] = critical.point;
        orbit["multiplicity"] = critical.multiplicity;
        addOrbit(orbit, critical.orbit);
        json["critical_orbits"].push_back(std::move(orbit));
    }
    return json;
}

template <typename Result>
void printJson(const Scene& scene, const Result& r, const std::optional<Connectedness>& k) {
    Json json;
    json["command"] = "orbit";
    if (scene.fractal.algebra != Algebra::kQuaternion)
        json["algebra"] = std::string(algebraName(scene.fractal.algebra));
    json["formula"] = scene.fractal.formula;
    json["c"] = cComponents(scene);
    json["z0"] = scene.orbit.z0;
    json["max_iterations"] = scene.orbit.maxIterations;
    addOrbit(json, r);
    json["cycle"] = r.cycle ? jsonCycle(scene, *r.cycle) : Json();
    json["escape_radius"] = r.escapeRadius;
    json["tolerance"] = r.tolerance;
    json["iterations"] = r.iterations;
    json["connectedness"] = k ? jsonConnectedness(*k) : Json();
    std::printf("%s\n", jsonText(json).c_str());
}

template <typename Result>
int report(const OrbitCommandOptions& options, const Scene& scene, const Result& result,
           const std::optional<Connectedness>& k) {
    if (options.json) {
        printJson(scene, result, k);
    } else {
        printText(scene, result, k);
    }
    return 0;
}

// The orbit in another algebra (orbit.h): z0 gives components 0 .. 3, the rest are 0.
int runHypercomplexOrbit(const OrbitCommandOptions& options, const Scene& scene) {
    const auto fractal = hypercomplexFractalFromScene(scene);
    const HypercomplexJuliaSet& set = *fractal.setAs<HypercomplexJuliaSet>();
    OrbitOptions orbitOptions;
    orbitOptions.maxIterations = scene.orbit.maxIterations;
    const Quaternion& z = scene.orbit.z0;
    const Hypercomplex z0{z.w, z.x, z.y, z.z, 0, 0, 0, 0};
    // Where the formula restricts to a copy of C, it is there the complex polynomial it is in
    // H (HypercomplexFormula::complexAxis): K's connectedness is that polynomial's.
    std::optional<Connectedness> k;
    if (set.formula().complexAxis()) {
        const auto restriction =
            restrictToComplexPlane(compileFormula(scene.fractal.formula, scene.fractal.c));
        if (restriction) k = connectedness(restriction->polynomial, scene.orbit.maxIterations);
    }
    return std::visit([&](const auto& result) { return report(options, scene, result, k); },
                      analyzeOrbit(set, z0, orbitOptions));
}

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
    Scene scene = orbitScene(options);
    if (scene.fractal.algebra != Algebra::kQuaternion) return runHypercomplexOrbit(options, scene);
    Polynomial p = compileMap(scene.fractal.formula, scene.fractal.c, formulaName(options.map));
    OrbitOptions orbitOptions;
    orbitOptions.maxIterations = scene.orbit.maxIterations;
    OrbitResult result = analyzeOrbit(p, scene.orbit.z0, orbitOptions);
    // Connectedness is about the complex restriction's K (docs/facts.md, Mandelbrot set).
    std::optional<Connectedness> k;
    if (auto restriction = restrictToComplexPlane(p)) {
        k = connectedness(restriction->polynomial, scene.orbit.maxIterations);
    }
    return report(options, scene, result, k);
}

}  // namespace quaternia
