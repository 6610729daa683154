#include "quaternia/algebra/constant_text.h"

#include <algorithm>
#include <cmath>

#include "quaternia/algebra/formula.h"
#include "quaternia/util/error.h"
#include "quaternia/util/number_format.h"

namespace quaternia {
namespace {

// The components of q, with rounding residue below 1e-12 of max(1, the largest) set to zero.
Quaternion chopped(Quaternion q) {
    double largest = std::max({1.0, std::abs(q.w), std::abs(q.x), std::abs(q.y), std::abs(q.z)});
    for (int k = 0; k < 4; ++k) {
        if (std::abs(q[k]) <= 1e-12 * largest) q[k] = 0;
    }
    return q;
}

}  // namespace

Quaternion parseConstant(const std::string& text, const std::string& option) {
    const std::string hint = " (a constant such as -1, 0.25+0.5i or 1+2i-0.5j+k)";
    Polynomial p = compileFormula(text, Quaternion(0), option);
    if (Formula::parse(text).usesC() || p.degree() != 0) {
        throw UserError(option, option + ": '" + text + "' is not a constant" + hint);
    }
    Quaternion value = p.evaluate(Quaternion(0));
    if (!isFinite(value)) {
        throw UserError(option, option + ": '" + text + "' is not finite" + hint);
    }
    return value;
}

std::string formatQuaternion(const Quaternion& q) {
    Quaternion c = chopped(q);
    std::string text;
    if (c.w != 0) text = roundedNumber(c.w, kReportDigits);
    const char* units[] = {"i", "j", "k"};
    for (int k = 1; k < 4; ++k) {
        double v = c[k];
        if (v == 0) continue;
        if (!text.empty())
            text += v < 0 ? "-" : "+";
        else if (v < 0)
            text += "-";
        std::string magnitude = roundedNumber(std::abs(v), kReportDigits);
        if (magnitude != "1") text += magnitude;
        text += units[k - 1];
    }
    return text.empty() ? "0" : text;
}

std::string formatComplex(std::complex<double> z) {
    return formatQuaternion(Quaternion(z.real(), z.imag(), 0, 0));
}

}  // namespace quaternia
