#include "quaternia/image/mask_compare.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace quaternia {
namespace {

// A filled axis-aligned rectangle [x0, x1) x [y0, y1).
Mask rectangle(int width, int height, int x0, int y0, int x1, int y1) {
    Mask mask = Mask::blank(width, height);
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x)
            mask.set(x, y, true);
    }
    return mask;
}

TEST(MaskCompare, CountsAndIouOfOverlappingRectangles) {
    // A: 4 x 4 = 16 pixels at (2..5, 2..5); B: 4 x 2 = 8 pixels at (4..7, 3..4).
    // Overlap (4..5, 3..4) = 4 pixels, union 16 + 8 - 4 = 20.
    Mask a = rectangle(10, 8, 2, 2, 6, 6);
    Mask b = rectangle(10, 8, 4, 3, 8, 5);
    MaskComparison c = compareMasks(a, b);
    EXPECT_EQ(c.countA, 16);
    EXPECT_EQ(c.countB, 8);
    EXPECT_EQ(c.intersection, 4);
    EXPECT_EQ(c.unionCount, 20);
    EXPECT_DOUBLE_EQ(c.iou, 4.0 / 20.0);
    // B dilated covers x 3..8, y 2..5: A's column x = 2 (4 pixels) is far from B.
    EXPECT_EQ(c.farFromB, 4);
    // A dilated covers x 1..6, y 1..6: B's column x = 7 (2 pixels) is far from A.
    EXPECT_EQ(c.farFromA, 2);
}

TEST(MaskCompare, IdenticalMasksHaveIouOneAndNothingFar) {
    Mask a = rectangle(7, 5, 1, 1, 4, 3);
    MaskComparison c = compareMasks(a, a);
    EXPECT_EQ(c.iou, 1.0);
    EXPECT_EQ(c.intersection, 6);
    EXPECT_EQ(c.unionCount, 6);
    EXPECT_EQ(c.farFromA, 0);
    EXPECT_EQ(c.farFromB, 0);
}

TEST(MaskCompare, TwoEmptyMasksHaveIouOne) {
    MaskComparison c = compareMasks(Mask::blank(4, 3), Mask::blank(4, 3));
    EXPECT_EQ(c.iou, 1.0);
    EXPECT_EQ(c.unionCount, 0);
    MaskComparison none = compareMasks(Mask::blank(0, 0), Mask::blank(0, 0));
    EXPECT_EQ(none.iou, 1.0);
}

TEST(MaskCompare, OneEmptyMaskHasIouZeroAndEverythingFar) {
    Mask a = rectangle(5, 5, 1, 1, 3, 3);
    MaskComparison c = compareMasks(a, Mask::blank(5, 5));
    EXPECT_EQ(c.iou, 0.0);
    EXPECT_EQ(c.farFromB, 4);
    EXPECT_EQ(c.farFromA, 0);
}

// The one-pixel tolerance of the reference measures: a shift by one pixel (also diagonally)
// stays within the 8-neighbourhood dilation; a shift by two does not.
TEST(MaskCompare, ShiftByOnePixelIsNotFarButByTwoIs) {
    Mask a = rectangle(20, 20, 5, 5, 12, 10);  // 7 x 5
    Mask right1 = rectangle(20, 20, 6, 5, 13, 10);
    Mask diagonal1 = rectangle(20, 20, 6, 6, 13, 11);
    Mask right2 = rectangle(20, 20, 7, 5, 14, 10);

    MaskComparison one = compareMasks(a, right1);
    EXPECT_EQ(one.farFromB, 0);
    EXPECT_EQ(one.farFromA, 0);
    EXPECT_DOUBLE_EQ(one.iou, 30.0 / 40.0);
    MaskComparison diagonal = compareMasks(a, diagonal1);
    EXPECT_EQ(diagonal.farFromB, 0);
    EXPECT_EQ(diagonal.farFromA, 0);

    MaskComparison two = compareMasks(a, right2);
    EXPECT_EQ(two.farFromB, 5) << "A's left column";
    EXPECT_EQ(two.farFromA, 5) << "B's right column";
    EXPECT_DOUBLE_EQ(two.iou, 25.0 / 45.0);
}

TEST(MaskCompare, DilationStopsAtTheBorder) {
    // Pixels on the image border: the 3 x 3 neighbourhood is clipped, not wrapped.
    Mask a = Mask::blank(4, 4);
    a.set(0, 0, true);
    Mask b = Mask::blank(4, 4);
    b.set(3, 3, true);
    b.set(3, 0, true);
    MaskComparison c = compareMasks(a, b);
    EXPECT_EQ(c.farFromB, 1);
    EXPECT_EQ(c.farFromA, 2);
}

TEST(MaskCompare, SizeMismatchThrows) {
    EXPECT_THROW(compareMasks(Mask::blank(4, 3), Mask::blank(3, 4)), std::invalid_argument);
    Mask broken{4, 4, std::vector<uint8_t>(15)};
    EXPECT_THROW(compareMasks(broken, Mask::blank(4, 4)), std::invalid_argument);
    EXPECT_THROW(differenceImage(Mask::blank(2, 2), Mask::blank(2, 3)), std::invalid_argument);
}

TEST(MaskCompare, DifferenceImageColoursEachCase) {
    Mask a = Mask::blank(2, 2), b = Mask::blank(2, 2);
    a.set(0, 0, true);  // both
    b.set(0, 0, true);
    a.set(1, 0, true);  // only A
    b.set(0, 1, true);  // only B
    Image image = differenceImage(a, b);
    ASSERT_EQ(image.width(), 2);
    ASSERT_EQ(image.height(), 2);
    EXPECT_EQ(image.at(0, 0), (Rgba{1, 1, 1, 1}));
    EXPECT_EQ(image.at(1, 0), (Rgba{1, 0, 0, 1}));
    EXPECT_EQ(image.at(0, 1), (Rgba{0, 0, 1, 1}));
    EXPECT_EQ(image.at(1, 1), (Rgba{0, 0, 0, 1}));
}

TEST(MaskCompare, DescribeNamesEveryMeasure) {
    MaskComparison c = compareMasks(rectangle(10, 8, 2, 2, 6, 6), rectangle(10, 8, 4, 3, 8, 5));
    EXPECT_EQ(describe(c), "iou 0.2000 (A 16, B 8, both 4, far from B 4, far from A 2)");
}

}  // namespace
}  // namespace quaternia
