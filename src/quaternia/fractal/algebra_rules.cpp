#include "quaternia/fractal/algebra_rules.h"

#include <array>
#include <stdexcept>

namespace quaternia {
namespace {

// The rows as written; escape is filled in by algebraRules().
// clang-format off
constexpr std::array<AlgebraRules, 5> kRules = {{
    // algebra               quaternion set  distance                  bailout  M at estimate  fold   duplex  H half
    {Algebra::kQuaternion,   true,           DistanceKind::kEstimate,  0,       true,          false, false,  false},
    {Algebra::kBicomplex,    false,          DistanceKind::kEstimate,  4,       false,         false, true,   false},
    {Algebra::kCoquaternion, false,          DistanceKind::kLipschitz, 2,       false,         false, false,  false},
    {Algebra::kBiquaternion, false,          DistanceKind::kLipschitz, 2,       false,         false, false,  true},
    {Algebra::kOctonion,     false,          DistanceKind::kEstimate,  0,       true,          true,  false,  true},
}};
// clang-format on

// Where orbits escape follows from the arithmetic: a multiplicative norm gives the radius from
// the top-degree part; the duplex form gives each component its own; otherwise none is certain.
EscapeRule escapeOf(const AlgebraRules& rules) {
    if (algebraArithmetic(rules.algebra).multiplicativeNorm) return EscapeRule::kMultiplicativeNorm;
    return rules.duplexForm ? EscapeRule::kDuplexComponents : EscapeRule::kNone;
}

}  // namespace

const AlgebraRules& algebraRules(Algebra algebra) {
    static const std::array<AlgebraRules, kRules.size()> rows = [] {
        std::array<AlgebraRules, kRules.size()> all = kRules;
        for (AlgebraRules& rules : all)
            rules.escape = escapeOf(rules);
        return all;
    }();
    for (const AlgebraRules& rules : rows)
        if (rules.algebra == algebra) return rules;
    throw std::logic_error("algebraRules: unknown algebra");
}

}  // namespace quaternia
