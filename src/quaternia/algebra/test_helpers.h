// Small helpers shared by the unit tests.
#pragma once

#include <gtest/gtest.h>

#include <random>

#include "quaternia/algebra/quaternion.h"
#include "quaternia/util/error.h"

namespace quaternia::testing {

inline constexpr Quaternion kI = kUnitI, kJ = kUnitJ, kK = kUnitK;

// A quaternion with components uniform in [-scale, scale].
inline Quaternion randomQuaternion(std::mt19937& rng, double scale = 1.5) {
    std::uniform_real_distribution<double> u(-scale, scale);
    return {u(rng), u(rng), u(rng), u(rng)};
}

inline void expectNear(const Quaternion& actual, const Quaternion& expected,
                       double tolerance = 1e-12) {
    for (int k = 0; k < 4; ++k) {
        EXPECT_NEAR(actual[k], expected[k], tolerance)
            << "component " << k << " of " << actual << " vs " << expected;
    }
}

// The UserError that `action` throws; fails the test if it throws none.
template <typename Action>
UserError thrownError(Action action) {
    try {
        action();
    } catch (const UserError& error) {
        return error;
    }
    ADD_FAILURE() << "no UserError thrown";
    return UserError("", "");
}

}  // namespace quaternia::testing
