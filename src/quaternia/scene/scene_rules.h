// The rules a whole Scene must keep beyond the range of each value: validateScene (parameters.h)
// runs them in this order and reports the first that a scene breaks, so that a scene breaking
// several is always told of the same one. Each rule is one function in scene_rules.cpp, with
// the reason it exists.
#pragma once

#include <span>
#include <string_view>

#include "quaternia/scene/scene.h"

namespace quaternia {

struct SceneRule {
    std::string_view name;  // what it requires, for tests and readers: "slice.left is not zero"
    // Throws a UserError naming the key to change if `scene` breaks the rule; a rule for some
    // algebras only passes the others.
    void (*check)(const Scene& scene);
};

// Every rule, in the order validateScene checks them. A new rule goes where its message should
// come among the others: the first broken rule is the one a user sees.
std::span<const SceneRule> sceneRules();

}  // namespace quaternia
