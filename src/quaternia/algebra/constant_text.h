// Constants as `quaternia orbit` and `quaternia cycles` read and write them: a constant such as
// --c or --z0 read by the formula parser, and complex numbers and quaternions written in the same
// a+bi+cj+dk form that it reads back (the fuzz target fuzz/numbers_fuzzer.cpp checks both ways).
#pragma once

#include <complex>
#include <string>

#include "quaternia/algebra/quaternion.h"

namespace quaternia {

// A constant such as "-1", "0.25+0.5i" or "1+2i-0.5j+k", read by the formula parser: it must
// expand to a polynomial of degree 0 without the names z and c. Throws UserError naming
// `option` (e.g. "--c") otherwise.
Quaternion parseConstant(const std::string& text, const std::string& option);

// The significant digits of a reported number (util/number_format.h, roundedNumber).
inline constexpr int kReportDigits = 10;

// kReportDigits significant digits; components below 1e-12 of max(1, the largest component)
// (rounding residue, as in 1e-17 + 0.62i) and negative zeros print as 0: "-1+i", "-i", "0.25",
// "1+2i-0.5j+k".
std::string formatComplex(std::complex<double> z);
std::string formatQuaternion(const Quaternion& q);

}  // namespace quaternia
