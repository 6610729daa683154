// The parameter table: every scene setting declared once, with its name, type, default, range
// and help. This one table drives scene files, --set, --help, validation and the explorer's
// controls (/api/parameters); parameters.cpp holds the machinery that reads it. This file holds
// the sections of the set that is drawn, [fractal] and [slice], and joins every section into
// the table (parameter_sections.h).
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "quaternia/scene/parameter_builders.h"
#include "quaternia/scene/parameter_sections.h"
#include "quaternia/scene/parameters.h"

namespace quaternia {
namespace parameter_builders {
namespace {

// fractal.c: 4 components (1, i, j, k) for the 4-component algebras, 8 for biquaternions and
// octonions; the first 4 go to FractalSettings::c, the rest to cUpper, and cComponents records
// how many were given so that validateScene can check them against fractal.algebra.
Parameter constantParameter(std::string help) {
    Parameter p = makeParameter("fractal", "c", ParameterType::Components,
                                std::vector<double>{-0.2, 0.6, 0.2, 0.2}, -10, 10, std::move(help));
    p.lengths = {4, 8};
    p.apply = [](Scene& scene, const ParameterValue& value) {
        const auto& v = std::get<std::vector<double>>(value);
        FractalSettings& fractal = scene.fractal;
        for (std::size_t i = 0; i < 4; ++i) {
            fractal.c[int(i)] = v[i];
            fractal.cUpper[i] = v.size() == 8 ? v[4 + i] : 0.0;
        }
        fractal.cComponents = int(v.size());
    };
    p.read = [](const Scene& scene) -> ParameterValue {
        const FractalSettings& fractal = scene.fractal;
        std::vector<double> v(fractal.cComponents == 4 ? 4 : 8);
        for (std::size_t i = 0; i < v.size(); ++i)
            v[i] = i < 4 ? fractal.c[int(i)] : fractal.cUpper[i - 4];
        return v;
    };
    return p;
}

std::vector<std::pair<std::string, Algebra>> algebraChoices() {
    std::vector<std::pair<std::string, Algebra>> choices;
    for (Algebra algebra : allAlgebras())
        choices.emplace_back(std::string(algebraName(algebra)), algebra);
    return choices;
}

}  // namespace

// [fractal]: the set itself: the formula iterated, its algebra and constant, and when a point
// has escaped.
std::vector<Parameter> fractalParameters() {
    using S = Scene;
    using F = FractalSettings;
    return {
        textParameter("fractal", "formula", &S::fractal, &F::formula, "z^2 + c", 1, 1000,
                      "Quaternion polynomial in z iterated as z <- p(z) (eq. 2.10); c stands for "
                      "fractal.c, e.g. \"z^3 + c\" or \"i*z*j*z + c\""),
        choiceParameter("fractal", "algebra", &S::fractal, &F::algebra, "quaternion",
                        algebraChoices(),
                        "The algebra of z, c and the formula's constants (seed paper, section "
                        "2.3): quaternion, bicomplex (POV-Ray's hypercomplex), coquaternion, "
                        "biquaternion or octonion"),
        constantParameter("The constant c as its (1, i, j, k) components, 8 of them for the "
                          "biquaternion and octonion algebras; each c is another Julia set"),
        integerParameter("fractal", "max_iterations", &S::fractal, &F::maxIterations, 12, 1, 100000,
                         "Iterations before a point that has not escaped counts as inside; more "
                         "is finer detail and slower"),
        realParameter("fractal", "bailout", &S::fractal, &F::bailout, 0, 0, 1e6,
                      "A point escapes once |z| > bailout; 0 uses the polynomial's own escape "
                      "radius"),
    };
}

// [slice]: the 3D slice of the 4D (or 8D) set that is drawn, and its rotations in 4D.
std::vector<Parameter> sliceParameters() {
    using S = Scene;
    using L = SliceSettings;
    return {
        vectorParameter("slice", "normal", &S::slice, &L::normal, {0, 0, 0, 1}, -1000, 1000,
                        "Normal s = (x, y, z, w) of the 4D hyperplane s . q = distance that is "
                        "drawn, as POV-Ray's slice; w must not be 0"),
        realParameter("slice", "distance", &S::slice, &L::distance, 0, -100, 100,
                      "Offset of the slice hyperplane along its normal; sweeping it morphs "
                      "through the 4D set"),
        withMotion(vectorParameter("slice", "left", &S::slice, &L::left, {1, 0, 0, 0}, -1000, 1000,
                                   "Quaternion l (1, i, j, k), made unit: a point p is drawn iff "
                                   "l * s(p) * r is in the set"),
                   Motion::Rotation),
        withMotion(
            vectorParameter("slice", "right", &S::slice, &L::right, {1, 0, 0, 0}, -1000, 1000,
                            "Quaternion r (1, i, j, k), made unit: a point p is drawn iff "
                            "l * s(p) * r is in the set"),
            Motion::Rotation),
        withMotion(vectorParameter("slice", "angles", &S::slice, &L::anglesDegrees,
                                   {0, 0, 0, 0, 0, 0}, -360, 360,
                                   "Extra 4D rotations of the slice in degrees, in the planes "
                                   "(1,i), (1,j), (1,k), (i,j), (i,k), (j,k)"),
                   Motion::Angle),
        componentsParameter("slice", "origin", &S::slice, &L::origin, {}, {0, 4, 8}, -1000, 1000,
                            "Origin of the 3D slice in the 8-component algebras (biquaternion, "
                            "octonion): (x, y, z) stands for origin + x axes[0] + y axes[1] + "
                            "z axes[2]; empty: 0; 4 components: the rest 0"),
        componentsParameter("slice", "axes", &S::slice, &L::axes, {}, {0, 12, 24}, -1000, 1000,
                            "Three directions of the 8-component algebra spanning the slice, "
                            "orthonormalised in order; empty: e0, e1, e2 (the quaternion default "
                            "slice); 4 components each: the rest 0",
                            3),
    };
}

}  // namespace parameter_builders

std::vector<Parameter> buildParameterTable() {
    using namespace parameter_builders;
    std::vector<Parameter> table;
    for (auto section : {fractalParameters, sliceParameters, cameraParameters, renderParameters,
                         shadingParameters, sceneryParameters, planeParameters, meshParameters,
                         orbitParameters, cyclesParameters, animationParameters}) {
        std::vector<Parameter> entries = section();
        table.insert(table.end(), std::make_move_iterator(entries.begin()),
                     std::make_move_iterator(entries.end()));
    }
    return table;
}

}  // namespace quaternia
