#include "quaternia/cellmap/certify_set.h"

#include <cmath>

#include "quaternia/cellmap/box_maps.h"
#include "quaternia/fractal/hypercomplex_julia.h"
#include "quaternia/scene/scene_fractal.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

// Level 0 has at most this many cells along an axis.
constexpr int64_t kTopCells3D = 32, kTopCells2D = 64;

struct RealPolynomial {
    std::vector<double> coefficients;  // a_0 = 0 .. a_d
    Hypercomplex constant;             // the formula's constants plus c
};

// The scene's formula as sum a_k z^k + C with real a_k, c appearing only as a summand: compiled
// with c = 0 and with c = a generic imaginary quaternion, the two must differ in the constant
// alone, by that quaternion.
RealPolynomial realPolynomialOf(const Scene& scene) {
    const FractalSettings& fractal = scene.fractal;
    const Quaternion probe(0, 0.3125, -0.1875, 0.4375);
    const Polynomial withoutC = compileMap(fractal.formula, Quaternion(0));
    const Polynomial withProbe = compileMap(fractal.formula, probe);
    const auto a = withoutC.realForm(), b = withProbe.realForm();
    if (!a || !b)
        throw UserError("fractal.formula",
                        "fractal.formula: certify needs real coefficients (sum a_k z^k + c): no "
                        "reduction to 3D is known for imaginary or two-sided ones");
    const Quaternion shift = b->constant - a->constant;
    if (a->coefficients != b->coefficients || shift.w != probe.w || shift.x != probe.x ||
        shift.y != probe.y || shift.z != probe.z)
        throw UserError("fractal.formula",
                        "fractal.formula: certify needs c as a summand (sum a_k z^k + c), not "
                        "inside a product");
    RealPolynomial p;
    p.coefficients = a->coefficients;
    p.coefficients[0] = 0;
    const Hypercomplex c = cOfScene(scene);
    p.constant = c;
    p.constant[0] += a->constant.w;
    p.constant[1] += a->constant.x;
    p.constant[2] += a->constant.y;
    p.constant[3] += a->constant.z;
    return p;
}

int levelsFor(int64_t resolution, int64_t topCells) {
    int levels = 0;
    while ((resolution + (int64_t(1) << levels) - 1) >> levels > topCells)
        ++levels;
    return levels;
}

}  // namespace

void validateSetCertification(const Scene& scene) {
    switch (scene.fractal.algebra) {
        case Algebra::kQuaternion:
        case Algebra::kOctonion:
            realPolynomialOf(scene);
            return;
        case Algebra::kBicomplex: {
            const auto set = hypercomplexJuliaSetOf(scene.fractal);
            if (set->componentCoefficients(0).empty())
                throw UserError("fractal.formula",
                                "fractal.formula: certify takes bicomplex polynomials (the product "
                                "of two complex sets); functions have no escape radius to prove");
            return;
        }
        default:
            throw UserError("fractal.algebra",
                            "fractal.algebra: certify takes the quaternions, octonions and "
                            "bicomplex numbers; this algebra has null elements, so no escape "
                            "radius proves an orbit unbounded");
    }
}

SetCertification certifySet(const Scene& scene, int resolution, const WorkOptions& work,
                            uint64_t memoryLimitBytes) {
    validateSetCertification(scene);
    SetCertification result;
    CertifiedSet& set = result.set;
    set.algebra = scene.fractal.algebra;
    set.formula = scene.fractal.formula;
    set.c = cOfScene(scene);
    CellMappingOptions options;
    options.memoryLimitBytes = memoryLimitBytes;
    options.memoryKey = "--resolution";
    options.work = work;

    if (set.algebra == Algebra::kBicomplex) {
        set.space = CertifiedSpace::kProduct;
        const auto julia = hypercomplexJuliaSetOf(scene.fractal);
        const int levels = levelsFor(resolution, kTopCells2D);
        const int64_t top = (resolution + (int64_t(1) << levels) - 1) >> levels;
        result.cellsPerAxis = top << levels;
        for (size_t i = 0; i < 2; ++i) {
            const auto& coefficients = julia->componentCoefficients(i);
            std::vector<double> moduli;
            for (const auto& a : coefficients)
                moduli.push_back(std::abs(a));
            const double radius = escapeRadiusOfModuli(moduli);
            set.escapeRadius = std::max(set.escapeRadius, radius);
            const double size0 = 2 * radius / double(top);
            CellGrid grid(2, {-radius, -radius, 0}, {size0, size0, 1}, {top, top, 1}, 1,
                          CellClass::kUndecided);
            options.finestLevel = levels;
            result.reports.push_back(
                classifyCells(grid, complexPolynomialBoxMap(coefficients, 0, 0, radius), options));
            result.completed = result.completed && result.reports.back().completed;
            result.census.push_back(grid.census());
            set.grids.push_back(std::move(grid));
            if (!result.completed) return result;
        }
        return result;
    }

    set.space = CertifiedSpace::kReduced;
    const RealPolynomial p = realPolynomialOf(scene);
    const int dimension = algebraDimension(set.algebra);
    double imaginary = 0;
    for (int k = 1; k < dimension; ++k)
        imaginary += p.constant[k] * p.constant[k];
    imaginary = std::sqrt(imaginary);
    set.coefficients = p.coefficients;
    set.realConstant = p.constant[0];
    set.imaginaryConstant = imaginary;
    set.axis = Hypercomplex{};
    if (imaginary > 0)
        for (int k = 1; k < dimension; ++k)
            set.axis[k] = p.constant[k] / imaginary;
    else
        set.axis[1] = 1;
    std::vector<double> moduli;
    for (double a : p.coefficients)
        moduli.push_back(std::fabs(a));
    moduli[0] = std::hypot(set.realConstant, imaginary);
    const double radius = escapeRadiusOfModuli(moduli);
    set.escapeRadius = radius;
    const int levels = levelsFor(resolution, kTopCells3D);
    const int64_t top = (resolution + (int64_t(1) << levels) - 1) >> levels;
    result.cellsPerAxis = top << levels;
    const double size0 = 2 * radius / double(top);
    CellGrid grid(3, {-radius, -radius, 0}, {size0, size0, 0.5 * size0}, {top, top, top}, 1,
                  CellClass::kUndecided);
    options.finestLevel = levels;
    result.reports.push_back(classifyCells(
        grid, reducedPolynomialBoxMap(p.coefficients, set.realConstant, imaginary, radius),
        options));
    result.completed = result.reports.back().completed;
    result.census.push_back(grid.census());
    set.grids.push_back(std::move(grid));
    return result;
}

}  // namespace quaternia
