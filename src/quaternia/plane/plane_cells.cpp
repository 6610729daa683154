#include "quaternia/plane/plane_cells.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "quaternia/cellmap/box_maps.h"
#include "quaternia/image/plane_view.h"
#include "quaternia/plane/plane_render.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

// Level 0 has at most this many cells along an axis; the grid beyond the view is refined down
// to cells no smaller than the escape disc's diameter over this many.
constexpr int64_t kTopCells = 64;
constexpr int64_t kOutsideCells = 4096;
// The finest cells are pixels cut this many times in two along each axis: a cell's image
// touches cells up to a cell or two beyond it (its box, turned and wrapped, and the grid's
// snapping), so the undecided band is a few cells wide; quarter-pixel cells keep it within
// about three pixels for a fraction of the cost of sharper images.
constexpr int kSubPixelLevels = 3;

// The class of a pixel from its cell at `level` and, where refined, the cells below it.
uint8_t pixelClass(const CellGrid& grid, int level, const CellIndex& cell, int depth) {
    const uint8_t v = grid.valueAt(level, cell);
    if (v != kRefined) return v;
    if (depth == 0) return uint8_t(CellClass::kUndecided);
    uint8_t first = 0;
    for (int n = 0; n < 4; ++n) {
        const uint8_t child = pixelClass(
            grid, level + 1, {2 * cell[0] + (n & 1), 2 * cell[1] + (n >> 1), 0}, depth - 1);
        if (child == uint8_t(CellClass::kUndecided)) return child;
        if (n == 0)
            first = child;
        else if (child != first)
            return uint8_t(CellClass::kUndecided);
    }
    return first;
}

}  // namespace

void validatePlaneCells(const Scene& scene) {
    validatePlaneScene(scene);
    const PlaneKind kind = scene.plane.kind;
    if (kind != PlaneKind::Julia && kind != PlaneKind::JuliaBoundary)
        throw UserError("plane.kind",
                        "plane.kind: certify classifies the filled Julia set of a complex "
                        "polynomial (julia or julia-boundary), not this kind");
    const ComplexPolynomial p = complexRestrictionOfScene(planeDrawnScene(scene)).polynomial;
    if (p.degree() < 2)
        throw UserError("fractal.formula",
                        "fractal.formula: degree below 2 on the plane; its orbits need not escape");
}

PlaneCells certifyPlaneCells(const Scene& scene, const WorkOptions& work,
                             uint64_t memoryLimitBytes) {
    validatePlaneCells(scene);
    const PlaneView view = planeViewFromScene(scene);
    const ComplexPolynomial p = complexRestrictionOfScene(planeDrawnScene(scene)).polynomial;
    std::vector<double> moduli;
    PlaneCells result;
    for (const Complex& a : p.coefficients()) {
        moduli.push_back(std::abs(a));
        result.coefficients.push_back(a.real());
        result.coefficients.push_back(a.imag());
    }
    const double radius = escapeRadiusOfModuli(moduli);
    result.escapeRadius = radius;
    const int width = view.pixelWidth, height = view.pixelHeight;
    const double h = view.pixelSize();
    result.width = width, result.height = height, result.pixelArea = h * h;

    // Frame coordinates: p = e^(-i theta) (z - centre); pixel (px, py) is the square
    // [(px - W/2) h, (px + 1 - W/2) h] x [(H/2 - py - 1) h, (H/2 - py) h]. The disc |z| <= R has
    // its centre at e^(-i theta) (-centre) in the frame.
    const Complex turn = std::polar(1.0, -view.rotationDegrees * std::numbers::pi / 180);
    const Complex discCentre = view.rotationDegrees != 0 ? -view.centre * turn : -view.centre;
    auto span = [&](double centre, int pixels, int64_t& first, int64_t& last) {
        // finest-cell indices relative to the image's first pixel along the axis
        first = std::min<int64_t>(0, int64_t(std::floor((centre - radius) / h + 0.5 * pixels)) - 1);
        last =
            std::max<int64_t>(pixels, int64_t(std::ceil((centre + radius) / h + 0.5 * pixels)) + 1);
    };
    int64_t u0, u1, v0, v1;
    span(discCentre.real(), width, u0, u1);
    span(discCentre.imag(), height, v0, v1);
    const int64_t cellsU = u1 - u0, cellsV = v1 - v0;
    int levels = 0;  // the pixels' level
    while ((std::max(cellsU, cellsV) >> levels) > kTopCells)
        ++levels;
    const int finest = levels + kSubPixelLevels;
    const int64_t topU = (cellsU + (int64_t(1) << levels) - 1) >> levels;
    const int64_t topV = (cellsV + (int64_t(1) << levels) - 1) >> levels;
    const double size0 = std::ldexp(h, levels);
    const std::array<double, 3> lower{(double(u0) - 0.5 * width) * h,
                                      (double(v0) - 0.5 * height) * h, 0};
    CellGrid grid(2, lower, {size0, size0, 1}, {topU, topV, 1}, 1, CellClass::kUndecided);

    // Refinement: every undecided cell that touches the view, down to the pixels; beyond the
    // view down to kOutsideCells across the disc.
    // (down to the finest cells where the whole grid then has at most kOutsideCells across: a
    // trapped region beyond the view, about an attracting cycle, may need them)
    const auto cellsAcross = [&](int level) {
        const int64_t pixels = std::max(cellsU, cellsV);
        return level <= levels ? pixels >> (levels - level) : pixels << (level - levels);
    };
    int outsideLevel = 0;
    while (outsideLevel < finest && cellsAcross(outsideLevel + 1) <= kOutsideCells)
        ++outsideLevel;
    CellMappingOptions options;
    options.finestLevel = finest;
    options.memoryLimitBytes = memoryLimitBytes;
    options.memoryKey = "render.width";
    options.work = work;
    options.refineWhere = [&](int level, const CellIndex& c) {
        if (level < outsideLevel) return true;
        // the cell's extent in pixels (beyond the pixels' level, its pixel's)
        const int64_t firstU =
            level <= levels ? (c[0] << (levels - level)) + u0 : (c[0] >> (level - levels)) + u0;
        const int64_t firstV =
            level <= levels ? (c[1] << (levels - level)) + v0 : (c[1] >> (level - levels)) + v0;
        const int64_t across = level <= levels ? int64_t(1) << (levels - level) : 1;
        return firstU + across > 0 && firstU < width && firstV + across > 0 && firstV < height;
    };
    const BoxMap map =
        complexPolynomialBoxMap(p.coefficients(), view.centre, view.rotationDegrees, radius);
    result.report = classifyCells(grid, map, options);
    result.completed = result.report.completed;
    if (!result.completed) return result;

    result.classes.resize(size_t(width) * size_t(height));
    for (int py = 0; py < height; ++py)
        for (int px = 0; px < width; ++px) {
            const int64_t i = px - u0, j = (height - 1 - py) - v0;
            const uint8_t v = pixelClass(grid, levels, {i, j, 0}, kSubPixelLevels);
            result.classes[size_t(py) * size_t(width) + size_t(px)] = v;
            if (v == uint8_t(CellClass::kOutside))
                ++result.outside;
            else if (v == uint8_t(CellClass::kInside))
                ++result.inside;
            else
                ++result.undecided;
        }
    result.band = measureUndecidedBand(result.classes, width, height);
    return result;
}

}  // namespace quaternia
