// The one number formatter (number_format.h): each style's text, and that the exact styles read
// back to the same double.
#include "quaternia/util/number_format.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <limits>

namespace quaternia {
namespace {

TEST(NumberFormat, ShortestReadsBackExactly) {
    for (double x : {0.1, 1.0 / 3, -2.5e-300, 1e300, 16384.0, 6.02214076e23,
                     std::numeric_limits<double>::max(), std::numeric_limits<double>::denorm_min()})
        EXPECT_EQ(std::strtod(shortestNumber(x).c_str(), nullptr), x) << shortestNumber(x);
    EXPECT_EQ(shortestNumber(0.1), "0.1");
    EXPECT_EQ(shortestNumber(16384), "16384");
}

TEST(NumberFormat, TomlRealAlwaysReadsAsAFloat) {
    EXPECT_EQ(tomlReal(16384), "16384.0");
    EXPECT_EQ(tomlReal(-0.25), "-0.25");
    EXPECT_EQ(tomlReal(1e300), "1e+300");
    EXPECT_EQ(tomlReal(std::numeric_limits<double>::quiet_NaN()), "nan");
    EXPECT_EQ(tomlReal(-std::numeric_limits<double>::quiet_NaN()), "nan");
    EXPECT_EQ(tomlReal(-std::numeric_limits<double>::infinity()), "-inf");
}

TEST(NumberFormat, PlainNumberIsFixedWhereAPersonReadsIt) {
    EXPECT_EQ(plainNumber(16384), "16384");
    EXPECT_EQ(plainNumber(0.0001), "0.0001");
    EXPECT_EQ(plainNumber(-10000), "-10000");
    EXPECT_EQ(plainNumber(1e20), "1e+20");
    EXPECT_EQ(plainNumber(1e-9), "1e-09");
}

// The fuzz target numbers_fuzzer found that the largest double printed with 10 digits
// ("1.797693135e+308") lies beyond it, so --c refused the text the commands write.
TEST(NumberFormat, RoundedNumberKeepsTheLargestDoubleReadable) {
    const double largest = std::numeric_limits<double>::max();
    EXPECT_EQ(roundedNumber(largest, 10), "1.7976931348623157e+308");
    EXPECT_EQ(roundedNumber(1.0 / 3, 10), "0.3333333333");
    EXPECT_EQ(roundedNumber(-1e300, 10), "-1e+300");
    EXPECT_EQ(roundedNumber(-0.0, 10), "0");
    EXPECT_EQ(roundedNumber(-std::numeric_limits<double>::infinity(), 10), "-inf");
}

}  // namespace
}  // namespace quaternia
