// Numbers as orbit and cycles read and write them (number_text.h).
#include "cmd/number_text.h"

#include <gtest/gtest.h>

#include <limits>

namespace quaternia {
namespace {

// The fuzz target numbers_fuzzer found that the largest double printed with 10 digits
// ("1.797693135e+308") lies beyond it, so --c refused the text the commands write.
TEST(NumberText, LargestDoubleReadsBack) {
    const double largest = std::numeric_limits<double>::max();
    for (const Quaternion& q : {Quaternion(largest), Quaternion(0, -largest, 0, 0)}) {
        const std::string text = formatQuaternion(q);
        EXPECT_EQ(parseConstant(text, "--c"), q) << text;
    }
    EXPECT_EQ(formatReal(largest), "1.7976931348623157e+308");
}

TEST(NumberText, TenDigitsOtherwise) {
    EXPECT_EQ(formatQuaternion(Quaternion(0.25, 0.5, 0, -1)), "0.25+0.5i-k");
    EXPECT_EQ(formatReal(1.0 / 3), "0.3333333333");
    EXPECT_EQ(formatReal(-1e300), "-1e+300");
}

}  // namespace
}  // namespace quaternia
