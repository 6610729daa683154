#include "quaternia/dynamics/orbit_report.h"

#include <complex>
#include <variant>
#include <vector>

#include "quaternia/algebra/complex_polynomial.h"
#include "quaternia/algebra/constant_text.h"
#include "quaternia/algebra/formula.h"
#include "quaternia/fractal/hypercomplex_julia.h"
#include "quaternia/scene/scene_fractal.h"
#include "quaternia/util/number_format.h"

namespace quaternia {
namespace {

std::string classText(const Classification& c) {
    return toString(c.stability) + (c.unsure ? " (unsure)" : "");
}

// Points and c as text and JSON: quaternions (and the 4-component algebras) as a+bi+cj+dk,
// the 8-component algebras as their list of components, as the scene file writes them.
std::string pointText(Algebra, const Quaternion& q) {
    return formatQuaternion(q);
}

std::string pointText(Algebra algebra, const Hypercomplex& q) {
    const int dimension = algebraDimension(algebra);
    if (dimension == 4) return formatQuaternion(Quaternion(q[0], q[1], q[2], q[3]));
    std::string text = "[";
    for (int n = 0; n < dimension; ++n)
        text += (n ? ", " : "") + roundedNumber(q[size_t(n)], kReportDigits);
    return text + "]";
}

Json pointJson(Algebra, const Quaternion& q) {
    return q;
}

Json pointJson(Algebra algebra, const Hypercomplex& q) {
    return std::vector<double>(q.begin(), q.begin() + algebraDimension(algebra));
}

// "H" for the quaternions, else the algebra's name and the Jacobian's size.
std::string algebraLabel(Algebra algebra) {
    if (algebra == Algebra::kQuaternion) return "H";
    const int n = algebraDimension(algebra);
    return std::string(algebraName(algebra)) + " (" + std::to_string(n) + "x" + std::to_string(n) +
           ")";
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
std::string orbitText(const OrbitReport& report, const Result& r) {
    const Algebra algebra = report.algebra;
    const std::string in = algebra == Algebra::kQuaternion
                               ? ""
                               : " in the " + std::string(algebraName(algebra)) + " algebra";
    std::string text = "orbit of z0 = " + formatQuaternion(report.z0) + " under " + report.formula +
                       in + ", c = " + pointText(algebra, report.c) + "\n";
    text += "fate: " + fateText(r) + "\n";
    if (r.cycle) {
        const auto& cycle = *r.cycle;
        std::string points;
        for (const auto& w : cycle.points)
            points += (points.empty() ? "" : " -> ") + pointText(algebra, w);
        text += "cycle: " + points + "\n";
        if (cycle.multiplier) {
            text += "multiplier: " + formatComplex(*cycle.multiplier) +
                    " (|lambda| = " + formatComplex(std::abs(*cycle.multiplier)) + "), " +
                    classText(cycle.complexClass) + "\n";
        }
        std::string eigen;
        for (std::complex<double> e : cycle.eigenvalues)
            eigen += (eigen.empty() ? "" : ", ") + formatComplex(e);
        text += "in " + algebraLabel(algebra) + ": Jacobian eigenvalues " + eigen + ", " +
                classText(cycle.classInH) + "\n";
    }
    if (r.unsure) text += "unsure: " + (r.note.empty() ? "see the class" : r.note) + "\n";
    if (report.connectedness) text += "K: " + connectednessText(*report.connectedness) + "\n";
    return text;
}

template <typename Cycle>
Json cycleJson(Algebra algebra, const Cycle& cycle) {
    Json json;
    json["period"] = cycle.period();
    json["points"] = Json::array();
    for (const auto& w : cycle.points)
        json["points"].push_back(pointJson(algebra, w));
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

Json connectednessJson(const Connectedness& k) {
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
Json orbitJson(const OrbitReport& report, const Result& r) {
    Json json;
    json["command"] = "orbit";
    if (report.algebra != Algebra::kQuaternion)
        json["algebra"] = std::string(algebraName(report.algebra));
    json["formula"] = report.formula;
    const int dimension = algebraDimension(report.algebra);
    json["c"] = std::vector<double>(report.c.begin(), report.c.begin() + dimension);
    json["z0"] = report.z0;
    json["max_iterations"] = report.maxIterations;
    addOrbit(json, r);
    json["cycle"] = r.cycle ? cycleJson(report.algebra, *r.cycle) : Json();
    json["escape_radius"] = r.escapeRadius;
    json["tolerance"] = r.tolerance;
    json["iterations"] = r.iterations;
    json["connectedness"] =
        report.connectedness ? connectednessJson(*report.connectedness) : Json();
    return json;
}

// The orbit in another algebra (orbit.h): z0 gives components 0 .. 3, the rest are 0.
void analyzeHypercomplex(const Scene& scene, OrbitReport& report) {
    const auto fractal = hypercomplexFractalFromScene(scene);
    const HypercomplexJuliaSet& set = *fractal.setAs<HypercomplexJuliaSet>();
    OrbitOptions options;
    options.maxIterations = scene.orbit.maxIterations;
    const Quaternion& z = scene.orbit.z0;
    const Hypercomplex z0{z.w, z.x, z.y, z.z, 0, 0, 0, 0};
    // Where the formula restricts to a copy of C, it is there the complex polynomial it is in
    // H (HypercomplexFormula::complexAxis): K's connectedness is that polynomial's.
    if (set.formula().complexAxis()) {
        const auto restriction =
            restrictToComplexPlane(compileFormula(scene.fractal.formula, scene.fractal.c));
        if (restriction)
            report.connectedness =
                connectedness(restriction->polynomial, scene.orbit.maxIterations);
    }
    report.orbit = analyzeOrbit(set, z0, options);
}

}  // namespace

OrbitReport orbitReport(const Scene& scene, const std::string& formulaName) {
    OrbitReport report;
    report.algebra = scene.fractal.algebra;
    report.formula = scene.fractal.formula;
    report.c = cOfScene(scene);
    report.z0 = scene.orbit.z0;
    report.maxIterations = scene.orbit.maxIterations;
    if (scene.fractal.algebra != Algebra::kQuaternion) {
        analyzeHypercomplex(scene, report);
        return report;
    }
    Polynomial p = compileMap(scene.fractal.formula, scene.fractal.c, formulaName);
    OrbitOptions options;
    options.maxIterations = scene.orbit.maxIterations;
    report.orbit = analyzeOrbit(p, scene.orbit.z0, options);
    // Connectedness is about the complex restriction's K (docs/facts.md, Mandelbrot set).
    if (auto restriction = restrictToComplexPlane(p))
        report.connectedness = connectedness(restriction->polynomial, scene.orbit.maxIterations);
    return report;
}

Json toJson(const OrbitReport& report) {
    return std::visit([&](const auto& r) { return orbitJson(report, r); }, report.orbit);
}

std::string toText(const OrbitReport& report) {
    return std::visit([&](const auto& r) { return orbitText(report, r); }, report.orbit);
}

}  // namespace quaternia
