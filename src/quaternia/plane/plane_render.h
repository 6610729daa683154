// 2D images of complex and quaternion dynamics (`quaternia plane`): the filled Julia set K_c
// with smooth escape colouring, the Julia set J_c drawn thin by its distance estimate, the
// Mandelbrot set of z^d + c, basins of attraction (basins.h), and any plane through H or,
// in the other algebras of fractal.algebra, through the set there (the slice kind). One view
// (PlaneView: centre, width, rotation, image size) for every kind; stratified samples per pixel
// as the 3D renderer takes them (samplePosition), tiles spread by the one parallel-for.
#pragma once

#include <cstdint>

#include "quaternia/algebra/complex_polynomial.h"
#include "quaternia/fractal/distance.h"
#include "quaternia/fractal/fractal.h"
#include "quaternia/image/image.h"
#include "quaternia/image/plane_view.h"
#include "quaternia/render/render.h"
#include "quaternia/render/sample_pattern.h"
#include "quaternia/scene/scene.h"

namespace quaternia {

using PlaneRenderOptions = WorkOptions;

struct PlaneImage {
    Image image;  // display values, alpha 1
    // Per pixel, row-major, of the pixel's first sample: the escape iteration for the escape
    // kinds (julia, julia-boundary, mandelbrot, slice; -1 where the orbit stayed), the basin for
    // basins (BasinImage::labels).
    std::vector<int32_t> labels;
    int64_t samples = 0;
    int threads = 0;
    double seconds = 0;
    bool completed = true;  // false if cancelled
};

// The view of plane.center, plane.width, plane.rotation at render.width x render.height.
PlaneView planeViewFromScene(const Scene& scene);

// The complex polynomial that fractal.formula with fractal.c restricts to (complex_polynomial.h;
// in another algebra, on its copy span{1, u} of C, as validatePlaneScene says),
// with the plane turned so that a formula in span{1, i} keeps its orientation (c = a - b i is
// drawn as itself, not as its mirror image a + b i). Throws UserError naming fractal.formula
// when the coefficients share no complex plane.
ComplexRestriction complexRestrictionOfScene(const Scene& scene);

// The sets the kinds iterate, plane.max_iterations times (what renderPlane draws, and what
// plane_certificate.h proves): the quaternions' set of fractal.formula with fractal.c and
// fractal.bailout (the julia kinds, and the slice kind in H), and in the other algebras the
// slice kind's HypercomplexJuliaSet with its slice (slice.origin, slice.axes). Throw UserError
// naming the key.
QuaternionJuliaSet planeJuliaSet(const Scene& scene);
Fractal planeHypercomplexFractal(const Scene& scene);
// The scene renderPlane draws for a kind other than slice: the scene itself in the quaternions;
// in another algebra, where the formula maps a copy span{1, u} of C into itself with every
// constant in it (HypercomplexFormula::complexAxis), the quaternion scene with c's components
// 0 .. 3, which has the same complex restriction (the formula acts on span{1, u} as on its copy
// in H). The Mandelbrot set of z^d + c is checked with c = 0.5 + 0.25 i: every other constant
// must then lie in span{1, i}. Throws UserError naming plane.kind and the algebra where there
// is no such plane.
Scene planeDrawnScene(const Scene& scene);
// The degree d of fractal.formula = z^d + c (the mandelbrot kind); throws UserError naming
// fractal.formula for a formula of another form.
int planeMultibrotDegree(const Scene& scene);

// validateScene, then what the chosen plane.kind needs: a complex restriction (julia kinds,
// basins), a formula z^d + c (mandelbrot), plane.u and plane.v neither zero nor parallel
// (slice), and a compilable formula. In the algebras other than the quaternions the complex
// kinds need a copy span{1, u} of C holding every constant (HypercomplexFormula::complexAxis;
// they draw the quaternion scene with the same restriction, and name plane.kind where there is
// none); for the 8-component ones the slice kind's plane lies in the 3D slice of slice.origin
// and slice.axes, so plane.origin, plane.u and plane.v must have a zero fourth component.
// Throws UserError naming the key to change.
void validatePlaneScene(const Scene& scene);

// An upper bound of the memory renderPlane and encodePng of its image take beyond a small fixed
// amount: the float image, as much again for the basins' per-pixel work, and the PNG twice.
uint64_t planeMemoryBytes(const Scene& scene);

// Validates (above), then draws the image of plane.kind.
PlaneImage renderPlane(const Scene& scene, const PlaneRenderOptions& options = {});

// The escape palette: a cosine gradient (Quilez, "palettes") of the smooth escape count, in
// display values.
Color escapeColor(double smoothIteration);
// Points that never escaped (the set itself), and the dark ground of julia-boundary.
Color interiorColor();
// The line of J_c in julia-boundary.
Color boundaryColor();

}  // namespace quaternia
