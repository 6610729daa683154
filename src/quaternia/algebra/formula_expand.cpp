// The expansion of a parsed formula (formula_tree.h) into the terms a0 z a1 ... z ad of a
// Polynomial: every product multiplied out in the order of its factors, like terms combined.
#include "quaternia/algebra/formula.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "quaternia/algebra/formula_tree.h"
#include "quaternia/util/error.h"

namespace quaternia {

namespace {

constexpr int kMaxDegree = 64;
constexpr size_t kMaxTerms = 4096;

// ---- Expansion -------------------------------------------------------------------------------

using Terms = std::vector<Term>;

[[noreturn]] void tooLarge(const std::string& why) {
    throw FormulaError(0, "formula too large: " + why);
}

constexpr const char* kOverflow = "a coefficient is not finite (overflow)";

// Terms are alike when their coefficients after the first are equal (==, so -0 is +0); the hash
// of those coefficients agrees for like terms.
std::uint64_t tailHash(const Term& term) {
    std::uint64_t hash = term.coefficients.size();
    for (std::size_t i = 1; i < term.coefficients.size(); ++i) {
        const Quaternion& a = term.coefficients[i];
        for (const double v : {a.w, a.x, a.y, a.z}) {
            hash = (hash ^ std::bit_cast<std::uint64_t>(v == 0 ? 0.0 : v)) * 0x9E3779B97F4A7C15u;
            hash ^= hash >> 29;
        }
    }
    return hash;
}

bool sameTail(const Term& a, const Term& b) {
    return a.coefficients.size() == b.coefficients.size() &&
           std::equal(a.coefficients.begin() + 1, a.coefficients.end(), b.coefficients.begin() + 1);
}

// Adds like terms, a z a1 ... z ad + b z a1 ... z ad = (a + b) z a1 ... z ad, keeping
// first-occurrence order and adding in that order, and drops zero terms. Like terms are found
// through an open-addressing table of indices into the result: this is most of an expansion's
// time, and a search tree of copied coefficient lists cost several times more.
Terms combineLikeTerms(Terms terms) {
    constexpr std::uint32_t kEmpty = ~std::uint32_t(0);
    const std::size_t slotCount = std::bit_ceil(2 * terms.size() + 1);
    std::vector<std::uint32_t> slots(slotCount, kEmpty);
    Terms combined;
    combined.reserve(terms.size());
    for (Term& term : terms) {
        const std::vector<Quaternion>& a = term.coefficients;
        // Overflow is final (no later step makes an infinity or NaN finite), and NaN, equal to
        // nothing, would make every such term unlike all others.
        if (!std::all_of(a.begin(), a.end(), [](const Quaternion& q) { return isFinite(q); }))
            throw FormulaError(0, kOverflow);
        if (std::any_of(a.begin(), a.end(),
                        [](const Quaternion& q) { return q == Quaternion{}; })) {
            continue;
        }
        std::size_t slot = tailHash(term) & (slotCount - 1);
        while (slots[slot] != kEmpty && !sameTail(combined[slots[slot]], term))
            slot = (slot + 1) & (slotCount - 1);
        if (slots[slot] == kEmpty) {
            slots[slot] = std::uint32_t(combined.size());
            combined.push_back(std::move(term));
        } else {
            combined[slots[slot]].coefficients[0] += term.coefficients[0];
        }
    }
    std::erase_if(combined, [](const Term& t) { return t.coefficients[0] == Quaternion{}; });
    if (combined.size() > kMaxTerms) tooLarge("more than 4096 terms");
    return combined;
}

// (sum of a) (sum of b), each product a0 z ... z ad b0 z ... z be with ad b0 merged into one
// coefficient by the Hamilton product; the order of factors is kept, since H does not commute.
Terms multiply(const Terms& left, const Terms& right) {
    if (left.size() * right.size() > kMaxTerms) tooLarge("multiplying out gives over 4096 terms");
    Terms product;
    for (const Term& a : left) {
        for (const Term& b : right) {
            if (a.degree() + b.degree() > kMaxDegree) {
                tooLarge("degree " + std::to_string(a.degree() + b.degree()) +
                         " is above the limit of " + std::to_string(kMaxDegree));
            }
            Term t;
            t.coefficients.assign(a.coefficients.begin(), a.coefficients.end() - 1);
            t.coefficients.push_back(a.coefficients.back() * b.coefficients.front());
            t.coefficients.insert(t.coefficients.end(), b.coefficients.begin() + 1,
                                  b.coefficients.end());
            product.push_back(std::move(t));
        }
    }
    return combineLikeTerms(std::move(product));
}

Terms negate(Terms terms) {
    for (Term& t : terms)
        t.coefficients[0] = -t.coefficients[0];
    return terms;
}

Terms concatenate(Terms left, const Terms& right) {
    left.insert(left.end(), right.begin(), right.end());
    return combineLikeTerms(std::move(left));
}

}  // namespace

[[noreturn]] void refuseTranscendental(const FormulaNode& node) {
    const std::string what = node.kind == FormulaNode::Kind::kFunction
                                 ? std::string(formulaFunctionName(node.function)) + "()"
                                 : "a power that is not a non-negative integer";
    throw FormulaError(node.column, what +
                                        " is defined for fractal.algebra = \"bicomplex\" only "
                                        "(through its duplex form); the other algebras take "
                                        "polynomials");
}

namespace {

Terms expandNode(const FormulaNode& node, const Quaternion& c) {
    using Kind = FormulaNode::Kind;
    switch (node.kind) {
        case Kind::kConstant:
            return combineLikeTerms({Term{{node.value}}});
        case Kind::kZ:
            return {Term{{Quaternion(1), Quaternion(1)}}};
        case Kind::kC:
            return combineLikeTerms({Term{{c}}});
        case Kind::kSum:
            return concatenate(expandNode(*node.left, c), expandNode(*node.right, c));
        case Kind::kDifference:
            return concatenate(expandNode(*node.left, c), negate(expandNode(*node.right, c)));
        case Kind::kProduct:
            return multiply(expandNode(*node.left, c), expandNode(*node.right, c));
        case Kind::kNegate:
            return negate(expandNode(*node.left, c));
        case Kind::kPower: {
            const Terms base = expandNode(*node.left, c);
            Terms result = {Term{{Quaternion(1)}}};  // z^0 = 1, as for 0^0
            for (int n = 0; n < node.exponent; ++n)
                result = multiply(result, base);
            return result;
        }
        case Kind::kFunction:
        case Kind::kRealPower:
            refuseTranscendental(node);
    }
    return {};
}

}  // namespace

Polynomial Formula::expand(const Quaternion& c) const {
    if (!root_) return Polynomial();
    Terms terms = expandNode(*root_, c);
    for (const Term& t : terms) {
        for (const Quaternion& a : t.coefficients) {
            if (!isFinite(a)) throw FormulaError(0, kOverflow);
        }
    }
    return Polynomial(std::move(terms));
}

Polynomial compileFormula(std::string_view text, const Quaternion& c, const std::string& key) {
    try {
        return Formula::parse(text).expand(c);
    } catch (const FormulaError& error) {
        throw UserError(key, key + ": " + error.what());
    }
}

}  // namespace quaternia
