#include "quaternia/interval/function_forms.h"

#include <cmath>

namespace quaternia {
namespace {

using Complex = std::complex<double>;

// Relative error allowed for the library's complex functions and the few operations after them
// (header comment).
constexpr double kFunctionError = 0x1p-40;

}  // namespace

// |z| rounded up: the square root of a sum of two squares is within 2 ulps of |z| (std::hypot,
// which also avoids overflow, took a fifth of a bicomplex exp render); an overflow gives
// infinity, which proves nothing.
double upperAbs(const Complex& z) {
    return std::sqrt(z.real() * z.real() + z.imag() * z.imag()) * (1 + 0x1p-50) + 0x1p-1000;
}

bool hasFunctionForm(FormulaFunction f) {
    switch (f) {
        case FormulaFunction::kExp:
        case FormulaFunction::kSin:
        case FormulaFunction::kCos:
        case FormulaFunction::kSinh:
        case FormulaFunction::kCosh:
            return true;
        default:
            return false;
    }
}

ComplexForm functionOnForm(FormulaFunction f, const ComplexForm& w) {
    const Complex c = w.centre;
    const double reach = (upperAbs(w.slope) + w.radius) * (1 + 0x1p-50);  // D
    Complex value, derivative;
    double curvature = 0;  // M, a bound of |f''| on the disc of radius D about c
    switch (f) {
        case FormulaFunction::kExp:
            value = derivative = std::exp(c);
            curvature = std::exp(c.real() + reach);
            break;
        case FormulaFunction::kSin:
            value = std::sin(c);
            derivative = std::cos(c);
            curvature = std::cosh(std::fabs(c.imag()) + reach);
            break;
        case FormulaFunction::kCos:
            value = std::cos(c);
            derivative = -std::sin(c);
            curvature = std::cosh(std::fabs(c.imag()) + reach);
            break;
        case FormulaFunction::kSinh:
            value = std::sinh(c);
            derivative = std::cosh(c);
            curvature = std::cosh(std::fabs(c.real()) + reach);
            break;
        case FormulaFunction::kCosh:
            value = std::cosh(c);
            derivative = std::sinh(c);
            curvature = std::cosh(std::fabs(c.real()) + reach);
            break;
        default: {
            const double nan = std::nan("");
            return {Complex(nan, nan), Complex(nan, nan), nan};
        }
    }
    curvature *= 1 + kFunctionError;
    ComplexForm image;
    image.centre = value;
    image.slope = derivative * w.slope;
    const double gain = upperAbs(derivative) * (1 + kFunctionError);
    image.radius = (gain * w.radius + 0.5 * curvature * reach * reach +
                    kFunctionError * (upperAbs(value) + gain * upperAbs(w.slope))) *
                       (1 + 0x1p-40) +
                   0x1p-1000;
    return image;
}

}  // namespace quaternia
