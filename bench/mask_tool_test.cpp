#include "mask_tool.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace quaternia::bench {
namespace {

TEST(MaskTool, ParsesBothSourcesAndRefusesOthers) {
    EXPECT_EQ(parseMaskSource("alpha"), MaskSource::Alpha);
    EXPECT_EQ(parseMaskSource("luma"), MaskSource::Luma);
    EXPECT_THROW(parseMaskSource("Alpha"), std::invalid_argument);
    EXPECT_THROW(parseMaskSource(""), std::invalid_argument);
}

TEST(MaskTool, AlphaAndLumaReadDifferentChannels) {
    // Pixel 0: white and transparent (a POV-Ray hit); pixel 1: black and opaque (a Quaternia
    // or Mandelbulber2 hit on a dark surface); pixel 2: white and opaque; pixel 3: neither.
    Image image(4, 1);
    image.at(0, 0) = Rgba{1, 1, 1, 0};
    image.at(1, 0) = Rgba{0, 0, 0, 1};
    image.at(2, 0) = Rgba{1, 1, 1, 1};
    image.at(3, 0) = Rgba{0, 0, 0, 0};
    Mask alpha = maskOf(image, MaskSource::Alpha);
    Mask luma = maskOf(image, MaskSource::Luma);
    EXPECT_FALSE(alpha.at(0, 0));
    EXPECT_TRUE(alpha.at(1, 0));
    EXPECT_TRUE(alpha.at(2, 0));
    EXPECT_FALSE(alpha.at(3, 0));
    EXPECT_TRUE(luma.at(0, 0));
    EXPECT_FALSE(luma.at(1, 0));
    EXPECT_TRUE(luma.at(2, 0));
    EXPECT_FALSE(luma.at(3, 0));
}

TEST(MaskTool, JsonCarriesEveryMeasure) {
    Mask a = Mask::blank(3, 1), b = Mask::blank(3, 1);
    a.set(0, 0, true);
    a.set(1, 0, true);
    b.set(1, 0, true);
    EXPECT_EQ(comparisonJson(compareMasks(a, b)),
              "{\"iou\": 0.500000, \"count_a\": 2, \"count_b\": 1, \"intersection\": 1, "
              "\"union\": 2, \"far_from_b\": 0, \"far_from_a\": 0}");
}

}  // namespace
}  // namespace quaternia::bench
