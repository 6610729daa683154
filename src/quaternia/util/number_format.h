// Every number Quaternia writes as text goes through here, so that one value reads the same in a
// scene file, an error message, a formula and a command's report. The styles differ in what the
// reader needs: a scene file reads back exactly (tomlReal), a person reads a bound
// (plainNumber) or a rounded report (roundedNumber).
#pragma once

#include <string>

namespace quaternia {

// The shortest digits that read back to the same double (std::to_chars): "0.1", "1e+300",
// "16384", "nan", "inf".
std::string shortestNumber(double x);

// shortestNumber as TOML reads it: a '.0' where the digits alone would read as an integer
// ("16384.0"), and "nan", "inf", "-inf" whatever the sign bit of a NaN.
std::string tomlReal(double x);

// A bound for people: fixed notation where 1e-6 <= |x| < 1e15 ("16384", "0.0001", "-10000"),
// the shortest of fixed and scientific elsewhere; digits that read back exactly.
std::string plainNumber(double x);

// `digits` significant digits (printf's %g), "-0" written as "0"; where the rounded text lies
// beyond the largest double (and would not read back), all 17 digits.
std::string roundedNumber(double x, int digits);

}  // namespace quaternia
