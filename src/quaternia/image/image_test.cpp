#include "quaternia/image/image.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace quaternia {
namespace {

TEST(Image, IsRowMajorWithRowZeroAtTheTop) {
    Image image(3, 2);
    ASSERT_EQ(image.width(), 3);
    ASSERT_EQ(image.height(), 2);
    ASSERT_EQ(image.pixels().size(), 6u);
    EXPECT_EQ(image.at(2, 1), Rgba{}) << "new pixels are transparent black";
    image.at(1, 0) = Rgba{0.25f, 0.5f, 0.75f, 1.0f};
    image.at(0, 1).g = 1.0f;
    EXPECT_EQ(image.pixels()[1], (Rgba{0.25f, 0.5f, 0.75f, 1.0f}));
    EXPECT_EQ(image.pixels()[3].g, 1.0f);
}

TEST(Image, FrameSizedImagesStartTransparentAndCopy) {
    // 1280x720 float RGBA is 14 MB: calloc maps it fresh (ZeroedAllocator), and again after a free.
    for (int round = 0; round < 2; ++round) {
        Image image(1280, 720);
        for (const Rgba& pixel : image.pixels())
            ASSERT_EQ(pixel, Rgba{});
        image.at(0, 0) = Rgba{1, 2, 3, 4};
        image.at(1279, 719) = Rgba{5, 6, 7, 8};
        Image copy = image;
        EXPECT_EQ(copy.at(0, 0), (Rgba{1, 2, 3, 4}));
        EXPECT_EQ(copy.at(1279, 719), (Rgba{5, 6, 7, 8}));
        EXPECT_EQ(copy.at(640, 360), Rgba{});
    }
}

TEST(Image, DefaultIsEmptyAndNegativeSizeThrows) {
    Image image;
    EXPECT_EQ(image.width(), 0);
    EXPECT_EQ(image.height(), 0);
    EXPECT_TRUE(image.pixels().empty());
    EXPECT_THROW(Image(-1, 4), std::invalid_argument);
    EXPECT_THROW(GrayImage(4, -1), std::invalid_argument);
    EXPECT_THROW(Mask::blank(-2, 2), std::invalid_argument);
}

TEST(GrayImage, StoresOneFloatPerPixel) {
    GrayImage depth(4, 3);
    ASSERT_EQ(depth.pixels().size(), 12u);
    EXPECT_EQ(depth.at(3, 2), 0.0f);
    depth.at(3, 2) = 0.125f;
    EXPECT_EQ(depth.pixels()[11], 0.125f);
}

TEST(Mask, BlankSetAndCount) {
    Mask mask = Mask::blank(5, 4);
    ASSERT_EQ(mask.inside.size(), 20u);
    EXPECT_EQ(mask.count(), 0);
    mask.set(4, 3, true);
    mask.set(0, 1, true);
    EXPECT_TRUE(mask.at(4, 3));
    EXPECT_EQ(mask.inside[19], 1);
    EXPECT_EQ(mask.inside[5], 1);
    EXPECT_EQ(mask.count(), 2);
    mask.set(4, 3, false);
    EXPECT_EQ(mask.count(), 1);
}

TEST(Mask, FromAlphaIsStrictlyAboveTheThreshold) {
    Image image(4, 1);
    image.at(0, 0).a = 0.0f;
    image.at(1, 0).a = 0.5f;
    image.at(2, 0).a = 0.75f;
    image.at(3, 0) = Rgba{1, 1, 1, 0.25f};  // colour does not matter
    Mask half = maskFromAlpha(image);
    EXPECT_EQ(half.width, 4);
    EXPECT_EQ(half.height, 1);
    EXPECT_EQ(half.inside, (std::vector<uint8_t>{0, 0, 1, 0}));
    EXPECT_EQ(maskFromAlpha(image, 0.2f).inside, (std::vector<uint8_t>{0, 1, 1, 1}));
}

TEST(Mask, FromImageThresholdsLuminanceIgnoringAlpha) {
    Image image(5, 1);
    image.at(0, 0) = Rgba{1, 1, 1, 0};              // white, transparent: inside
    image.at(1, 0) = Rgba{0, 0, 0, 1};              // black: outside
    image.at(2, 0) = Rgba{0.5f, 0.5f, 0.5f, 1};     // exactly half: outside
    image.at(3, 0) = Rgba{0.51f, 0.51f, 0.51f, 1};  // inside
    image.at(4, 0) = Rgba{1, 0, 0, 1};              // red has luminance 0.2126: outside
    EXPECT_EQ(maskFromImage(image).inside, (std::vector<uint8_t>{1, 0, 0, 1, 0}));
}

}  // namespace
}  // namespace quaternia
