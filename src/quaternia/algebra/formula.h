// Formula strings for quaternion polynomials, e.g. "z^2 + c", "(1+2i) z (0.5-k) z + c",
// "i*z*j*z + c", "z*z*z + 0.5*z + c", "z^2 + (0.1 + 0.2j)*z + c".
//
// Grammar (whitespace ignored; juxtaposition multiplies, so "2z" and "(1+i) z" are products):
//   sum     := product (('+' | '-') product)*
//   product := unary (['*'] unary)*
//   unary   := ('+' | '-') unary | power
//   power   := primary ['^' non-negative integer]
//   primary := number ['i' | 'j' | 'k'] | 'i' | 'j' | 'k' | 'z' | 'c' | '(' sum ')'
// The name c is the scene's fractal.c, supplied when the formula is expanded.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>

#include "quaternia/algebra/polynomial.h"
#include "quaternia/algebra/quaternion.h"

namespace quaternia {

// A parse error at a 1-based column, with what was expected there.
class FormulaError : public std::runtime_error {
  public:
    FormulaError(int column, const std::string& message)
        : std::runtime_error(message), column_(column) {}
    int column() const { return column_; }

  private:
    int column_;
};

struct FormulaNode;  // the parsed expression tree (formula_tree.h)

// A parsed formula: cheap to copy, expanded into a Polynomial once c is known.
class Formula {
  public:
    // Throws FormulaError, whose message reads like
    // "column 7: expected a number, i, j, k, z, c or '(' but found ')'". Exponents are integer
    // literals up to 64; texts over 10000 characters or nested over 100 deep are refused.
    static Formula parse(std::string_view text);

    // Multiplies out every product (keeping the order of factors) and merges adjacent constant
    // factors. Throws FormulaError(0, ...) if the result exceeds degree 64 or 4096 terms.
    // Like terms (equal coefficients after the first) are added and zero terms dropped, so
    // "z^2 - z^2 + c" is the constant c and "(z + 1)^3" has 4 terms.
    Polynomial expand(const Quaternion& c) const;
    // True if the name c occurs in the formula.
    bool usesC() const;
    const std::string& text() const { return text_; }
    // The parsed tree (formula_tree.h); null for a formula without terms.
    const FormulaNode* root() const { return root_.get(); }

  private:
    std::string text_;
    std::shared_ptr<const FormulaNode> root_;
};

// Parses and expands in one step, turning a FormulaError into a UserError naming `key` (default
// "fractal.formula") with the column, e.g. "fractal.formula: column 7: expected ...".
Polynomial compileFormula(std::string_view text, const Quaternion& c,
                          const std::string& key = "fractal.formula");

}  // namespace quaternia
