#include "quaternia/fractal/algebra_rules.h"

#include <array>
#include <stdexcept>

namespace quaternia {
namespace {

// clang-format off
constexpr std::array<AlgebraRules, 5> kRules = {{
    // algebra               quaternion set  distance                  escape                          bailout  M at estimate  fold   duplex
    {Algebra::kQuaternion,   true,           DistanceKind::kEstimate,  EscapeRule::kMultiplicativeNorm, 0,       true,          false, false},
    {Algebra::kBicomplex,    false,          DistanceKind::kEstimate,  EscapeRule::kDuplexComponents,   4,       false,         false, true},
    {Algebra::kCoquaternion, false,          DistanceKind::kLipschitz, EscapeRule::kNone,               2,       false,         false, false},
    {Algebra::kBiquaternion, false,          DistanceKind::kLipschitz, EscapeRule::kNone,               2,       false,         false, false},
    {Algebra::kOctonion,     false,          DistanceKind::kEstimate,  EscapeRule::kMultiplicativeNorm, 0,       true,          true,  false},
}};
// clang-format on

}  // namespace

const AlgebraRules& algebraRules(Algebra algebra) {
    for (const AlgebraRules& rules : kRules)
        if (rules.algebra == algebra) return rules;
    throw std::logic_error("algebraRules: unknown algebra");
}

}  // namespace quaternia
