// The bicomplex functions (POV-Ray's hypercomplex functions, applied to each duplex component,
// algebra/hypercomplex.h) on the forms of this layer: each duplex component of a box or a
// segment form is a complex form c + s e + u, e in [-1, 1] shared with the segment, |u| <= rho,
// and an analytic f maps it into f(c) + f'(c) s e + u' by Taylor's theorem with the remainder:
// |f(c + d) - f(c) - f'(c) d| <= M |d|^2 / 2 for |d| <= D = |s| + rho, M a bound of |f''| on the
// disc |w - c| <= D, and f'(c) u adds |f'(c)| rho (Moore, Kearfott and Cloud, "Introduction to
// Interval Analysis", 2009, chapter 6, the mean-value and Taylor forms). The entire functions
// have such bounds in closed form (w = x + i y):
//   exp:        |exp''(w)| = e^x                     <= e^(Re c + D)
//   sin, cos:   |sin w|, |cos w| <= cosh y           <= cosh(|Im c| + D)
//   sinh, cosh: |sinh w|, |cosh w| <= cosh x         <= cosh(|Re c| + D)
// (|sin(x + iy)|^2 = sin^2 x + sinh^2 y, |cos(x + iy)|^2 = cos^2 x + sinh^2 y, and sinh, cosh
// likewise with x and y exchanged.) The other functions have poles or branch cuts and no form
// here yet (hasFunctionForm). Rounding: std::complex's exp, sin, cos, sinh and cosh are glibc's
// cexp, csin, ccos, csinh, ccosh, within a few ulps of the exact value (the glibc manual's table
// "Known Maximum Errors in Math Functions"); the forms add 2^-40 of the moduli, a thousand times
// that, and every bound of M is raised by the same factor.
#pragma once

#include <complex>

#include "quaternia/algebra/formula_tree.h"

namespace quaternia {

// One duplex component of a form: the points centre + slope e + u, |u| <= radius (slope 0 for a
// box's).
struct ComplexForm {
    std::complex<double> centre, slope;
    double radius = 0;
};

// Whether functionOnForm takes f: exp, sin, cos, sinh and cosh.
bool hasFunctionForm(FormulaFunction f);

// Encloses {f(w) : w in the form} in a form of the same e (header comment). Infinite or NaN
// where f overflows: such a form proves nothing.
ComplexForm functionOnForm(FormulaFunction f, const ComplexForm& w);
// |z| rounded up (for the forms' rounding terms).
double upperAbs(const std::complex<double>& z);

}  // namespace quaternia
