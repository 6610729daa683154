#include "quaternia/dynamics/cycles_report.h"

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <vector>

#include "quaternia/algebra/constant_text.h"
#include "quaternia/scene/scene_fractal.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

ComplexRestriction complexMap(const Scene& scene, const std::string& formulaName) {
    Polynomial p = compileMap(scene.fractal.formula, scene.fractal.c, formulaName);
    std::optional<ComplexRestriction> restriction = restrictToComplexPlane(p);
    if (!restriction) {
        throw UserError(formulaName,
                        formulaName +
                            ": cycles needs a complex polynomial, but the coefficients of " +
                            p.toString() + " do not lie in one plane C_u = span{1, u}");
    }
    return *restriction;
}

// The table bounds the period for degree 2; higher degrees allow less.
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

// printf's formatting appended to `text`: the table's columns are printf widths (std::format
// is not in every compiler the project supports).
[[gnu::format(printf, 2, 3)]] void appendf(std::string& text, const char* format, ...) {
    va_list args;
    va_start(args, format);
    va_list again;
    va_copy(again, args);
    const int size = std::vsnprintf(nullptr, 0, format, args);
    va_end(args);
    std::vector<char> line(size_t(size) + 1);
    std::vsnprintf(line.data(), line.size(), format, again);
    va_end(again);
    text.append(line.data(), size_t(size));
}

}  // namespace

CyclesReport cyclesReport(const Scene& scene, const std::string& formulaName,
                          const std::string& periodName) {
    requireQuaternionAlgebra(scene, "cycles");
    CyclesReport report;
    report.formula = scene.fractal.formula;
    report.c = scene.fractal.c;
    report.map = complexMap(scene, formulaName);
    checkPeriod(scene.cycles.period, report.map.polynomial.degree(), periodName);
    report.points = periodicPoints(report.map.polynomial, scene.cycles.period);
    return report;
}

Json toJson(const CyclesReport& report) {
    const PeriodicPoints& points = report.points;
    Json json;
    json["command"] = "cycles";
    json["formula"] = report.formula;
    json["c"] = report.c;
    json["plane_axis"] = report.map.axis;
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
    return json;
}

std::string toText(const CyclesReport& report) {
    const PeriodicPoints& points = report.points;
    std::string text;
    appendf(text, "%s with c = %s: %lld point%s of period %d in %zu cycle%s\n",
            report.formula.c_str(), formatQuaternion(report.c).c_str(),
            static_cast<long long>(points.count), points.count == 1 ? "" : "s", points.period,
            points.cycles.size(), points.cycles.size() == 1 ? "" : "s");
    if (norm(report.map.axis - kUnitI) > 1e-12) {
        appendf(text, "(complex numbers x+yi stand for x + y u in the plane C_u, u = %s)\n",
                formatQuaternion(report.map.axis).c_str());
    }
    appendf(text, "%4s  %-28s %-13s %-16s %s\n", "#", "multiplier", "|multiplier|", "class",
            "points");
    for (std::size_t i = 0; i < points.cycles.size(); ++i) {
        const PeriodicCycle& cycle = points.cycles[i];
        std::string list;
        for (std::complex<double> z : cycle.points)
            list += (list.empty() ? "" : " -> ") + formatComplex(z);
        appendf(text, "%4zu  %-28s %-13s %-16s %s%s\n", i + 1,
                formatComplex(cycle.multiplier).c_str(),
                formatComplex(std::abs(cycle.multiplier)).c_str(),
                toString(cycle.classification.stability).c_str(), list.c_str(),
                cycleNote(cycle).c_str());
    }
    return text;
}

}  // namespace quaternia
