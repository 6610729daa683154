// Shared by `quaternia orbit` and `quaternia cycles`: the short flags --formula and --c that set
// [fractal]'s map, reading --c and --z0, and writing complex numbers and quaternions in the same
// a+bi+cj+dk form that --c reads back.
#pragma once

#include <complex>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "quaternia/algebra/polynomial.h"
#include "quaternia/algebra/quaternion.h"
#include "quaternia/scene/scene.h"

namespace quaternia {

// --formula sets fractal.formula, --c sets fractal.c (in parseConstant's syntax); unset, the
// scene's values stand.
struct MapFlags {
    std::optional<std::string> formula, c;
};

void addMapFlags(CLI::App& command, MapFlags& flags, const std::string& formulaHelp,
                 const std::string& cHelp);
// Applies the flags given (after --set). Throws UserError naming the flag.
void applyMapFlags(Scene& scene, const MapFlags& flags);
// What a message about the formula names: "--formula" where it came from the flag, otherwise
// "fractal.formula".
std::string formulaName(const MapFlags& flags);

// q as the table's (1, i, j, k) vector, for setParameter.
std::vector<double> quaternionValue(const Quaternion& q);

// A constant such as "-1", "0.25+0.5i" or "1+2i-0.5j+k", read by the formula parser: it must
// expand to a polynomial of degree 0 without the names z and c. Throws UserError naming
// `option` (e.g. "--c") otherwise.
Quaternion parseConstant(const std::string& text, const std::string& option);

// The map `formula` with c substituted. Throws UserError naming `name` (formulaName) when it
// does not parse, or when it has no escape radius (degree below 2, or possibly unbounded).
Polynomial compileMap(const std::string& formula, const Quaternion& c, const std::string& name);

// 10 significant digits; components below 1e-12 of max(1, the largest component) (rounding
// residue, as in 1e-17 + 0.62i) and negative zeros print as 0: "-1+i", "-i", "0.25",
// "1+2i-0.5j+k".
std::string formatComplex(std::complex<double> z);
std::string formatQuaternion(const Quaternion& q);
std::string formatReal(double value);

}  // namespace quaternia
