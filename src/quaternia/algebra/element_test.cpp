// One element type for every algebra (element.h): the quaternion is its 4-dimensional instance,
// whose written-out product is Hamilton's multiplication table, bit for bit.
#include "quaternia/algebra/element.h"

#include <gtest/gtest.h>

#include <random>

#include "quaternia/algebra/hypercomplex.h"
#include "quaternia/algebra/quaternion.h"

namespace quaternia {
namespace {

Hypercomplex asElement(const Quaternion& q) {
    return {q.w, q.x, q.y, q.z, 0, 0, 0, 0};
}

// The SIMD lanes and the scalar reference multiply quaternions by operator*; the other algebras
// by their tables. The two agree exactly on the quaternions, rounding included: the written-out
// product sums each component in the table's order.
TEST(Element, QuaternionProductIsHamiltonsTable) {
    std::mt19937 random(3);
    std::uniform_real_distribution<double> uniform(-2, 2);
    const MultiplicationTable& hamilton = MultiplicationTable::of(Algebra::kQuaternion);
    for (int trial = 0; trial < 1000; ++trial) {
        const Quaternion a(uniform(random), uniform(random), uniform(random), uniform(random));
        const Quaternion b(uniform(random), uniform(random), uniform(random), uniform(random));
        const Quaternion product = a * b;
        const Hypercomplex table = hamilton.multiply(asElement(a), asElement(b));
        for (int n = 0; n < 4; ++n)
            EXPECT_EQ(product[n], table[size_t(n)]) << "component " << n;
        for (int n = 4; n < 8; ++n)
            EXPECT_EQ(table[size_t(n)], 0);
    }
}

// Element<T, N> is templated on its scalar: the same components in float, and the 4-component
// instance is the quaternion type itself.
TEST(Element, IsTemplatedOnItsScalar) {
    static_assert(std::is_same_v<QuaternionT<float>, Element<float, 4>>);
    static_assert(std::is_same_v<Hypercomplex, Element<double, 8>>);
    const Element<float, 8> e{1.0f, 2.0f, 3.0f, 4.0f, 5.0f, 6.0f, 7.0f, 8.0f};
    EXPECT_EQ(e[7], 8.0f);
    const Quaternionf q(1.0f, 2.0f, 3.0f, 4.0f);
    EXPECT_EQ((q * q).w, 1.0f - 4.0f - 9.0f - 16.0f);
}

}  // namespace
}  // namespace quaternia
