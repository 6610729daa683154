// The Mandelbrot set M_d of z^d + c (d >= 2; M = M_2): the parameters c whose critical orbit
// 0, c, c^d + c, ... stays bounded, which are exactly those with K_c connected (Douady, Hubbard
// 1982; Milnor, Dynamics in One Complex Variable, Thm. 9.5). Escape-time membership with a
// smooth escape count and the distance estimate of the parameter plane, for images.
#pragma once

#include <complex>

#include "quaternia/algebra/quaternion.h"

namespace quaternia {

struct MandelbrotEstimate {
    bool inside = false;         // z_1 .. z_N all within the escape radius (N = maxIterations)
    int escapeIteration = 0;     // first n with |z_n| > escape radius; maxIterations when inside
    double smoothIteration = 0;  // continuous escape count, for colouring
    double distance = 0;         // lower-bound estimate of the distance to M_d; 0 inside
};

// The critical orbit z_0 = 0, z_{n+1} = z_n^d + c is iterated until |z_n| > max(2, |c|), which
// certifies escape: there |z^d + c| >= |z|^d - |c| > |z| (|z| - 1) >= |z| (1 + delta). After
// escaping it continues to |z| = 1e4 so that the smooth count and the estimate
// 0.5 |z| ln|z| / |z'| with z' = dz/dc, z'_{n+1} = d z_n^(d-1) z'_n + 1 (Douady-Hubbard potential;
// Milnor 1989, "Self-similarity and hairiness in the Mandelbrot set") are accurate.
MandelbrotEstimate estimateMandelbrot(std::complex<double> c, int maxIterations, int degree = 2);

bool inMandelbrotSet(std::complex<double> c, int maxIterations, int degree = 2);

// The quaternion Mandelbrot set of z^2 + c, iterated in H. The orbit of 0 stays in span{1, c},
// so membership equals that of Re c + |Im c| i (docs/facts.md, Mandelbrot set); tests
// hold the two together.
bool inQuaternionMandelbrotSet(const Quaternion& c, int maxIterations);

}  // namespace quaternia
