// Constants as orbit and cycles read and write them (constant_text.h).
#include "quaternia/algebra/constant_text.h"

#include <gtest/gtest.h>

#include <limits>

namespace quaternia {
namespace {

// The fuzz target numbers_fuzzer found that the largest double printed with 10 digits
// ("1.797693135e+308") lies beyond it, so --c refused the text the commands write.
TEST(ConstantText, LargestDoubleReadsBack) {
    const double largest = std::numeric_limits<double>::max();
    for (const Quaternion& q : {Quaternion(largest), Quaternion(0, -largest, 0, 0)}) {
        const std::string text = formatQuaternion(q);
        EXPECT_EQ(parseConstant(text, "--c"), q) << text;
    }
}

TEST(ConstantText, TenDigitsOtherwise) {
    EXPECT_EQ(formatQuaternion(Quaternion(0.25, 0.5, 0, -1)), "0.25+0.5i-k");
    EXPECT_EQ(formatQuaternion(Quaternion(1.0 / 3, 0, 0, 0)), "0.3333333333");
    EXPECT_EQ(formatComplex({-1e300, 0}), "-1e+300");
    EXPECT_EQ(formatComplex({-1e3, -1}), "-1000-i");
    EXPECT_EQ(formatQuaternion(Quaternion(-0.0, 1, 0, 0)), "i");
}

}  // namespace
}  // namespace quaternia
