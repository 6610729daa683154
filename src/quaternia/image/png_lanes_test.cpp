// The PNG lanes (png_lanes.h) against the scalar formulas they replaced, written out here,
// on every instruction set compiled in and supported here. Equal means byte for byte: the PNGs
// must not change.
#include "quaternia/image/png_lanes.h"

#include <gtest/gtest.h>

#include <hwy/targets.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>
#include <vector>

namespace quaternia {
namespace {

// png_io's quantisation before the lanes: clamped to [0, 1] (NaN to 0), rounded in double.
template <uint32_t MaxValue>
uint32_t quantiseReference(float value) {
    const float clamped = value > 0.0f ? (value < 1.0f ? value : 1.0f) : 0.0f;
    return uint32_t(double(clamped) * double(MaxValue) + 0.5);
}

// Samples of packed RGBA pixels, as png_io wrote them one at a time (16 bits big-endian).
std::vector<uint8_t> samplesReference(const std::vector<float>& rgba, int bitDepth,
                                      bool withAlpha) {
    std::vector<uint8_t> out;
    for (size_t i = 0; i < rgba.size(); ++i) {
        if (i % 4 == 3 && !withAlpha) continue;
        if (bitDepth == 8) {
            out.push_back(uint8_t(quantiseReference<255>(rgba[i])));
        } else {
            const uint32_t v = quantiseReference<65535>(rgba[i]);
            out.push_back(uint8_t(v >> 8));
            out.push_back(uint8_t(v & 0xff));
        }
    }
    return out;
}

// PNG spec 9.4's predictor, as png_writer computed it byte by byte.
int paethReference(int a, int b, int c) {
    const int p = a + b - c;
    const int pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
    if (pa <= pb && pa <= pc) return a;
    return pb <= pc ? b : c;
}

std::vector<uint8_t> filterReference(const std::vector<uint8_t>& row,
                                     const std::vector<uint8_t>& previous, size_t bytesPerPixel) {
    std::vector<uint8_t> out(row.size());
    for (size_t i = 0; i < row.size(); ++i) {
        const int a = i >= bytesPerPixel ? row[i - bytesPerPixel] : 0;
        const int c = i >= bytesPerPixel ? previous[i - bytesPerPixel] : 0;
        out[i] = uint8_t(row[i] - paethReference(a, previous[i], c));
    }
    return out;
}

// Floats that quantisation must get right: the ends, values outside [0, 1], infinities, NaNs,
// denormals, and the floats around each rounding threshold (n + 1/2) / max of 8 and 16 bits,
// where a product rounded to float would err.
std::vector<float> hardValues() {
    const float inf = std::numeric_limits<float>::infinity();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::vector<float> values = {0.0f,
                                 -0.0f,
                                 1.0f,
                                 -1.0f,
                                 2.0f,
                                 1e30f,
                                 -1e30f,
                                 inf,
                                 -inf,
                                 nan,
                                 -nan,
                                 std::numeric_limits<float>::denorm_min(),
                                 std::numeric_limits<float>::min(),
                                 0.5f,
                                 std::nextafter(1.0f, 0.0f),
                                 std::nextafter(1.0f, 2.0f)};
    for (double maxValue : {255.0, 65535.0}) {
        for (double n = 0; n < maxValue; ++n) {
            float near = float((n + 0.5) / maxValue);
            for (int step = 0; step < 3; ++step)
                near = std::nextafter(near, 0.0f);
            for (int step = 0; step < 7; ++step) {
                values.push_back(near);
                near = std::nextafter(near, 1.0f);
            }
        }
    }
    return values;
}

// Quantisation of random and hard values, with and without alpha, at 8 and 16 bits, for pixel
// counts that are not multiples of any vector length; and the Paeth filter of random rows of
// every byte value, for each PNG pixel size, with row lengths around the vector lengths.
TEST(PngLanes, SimdQuantiseAndPaethEqualTheScalarFormulas) {
    std::mt19937 random(7);
    std::uniform_real_distribution<float> wide(-0.5f, 1.5f);
    const std::vector<float> hard = hardValues();
    std::vector<float> rgba(hard.size() + 4 * 1001);
    std::copy(hard.begin(), hard.end(), rgba.begin());
    for (size_t i = hard.size(); i < rgba.size(); ++i)
        rgba[i] = wide(random);
    std::shuffle(rgba.begin(), rgba.end(), random);  // hard values in every channel
    rgba.resize(rgba.size() / 4 * 4);

    for (int64_t target : hwy::SupportedAndGeneratedTargets()) {
        hwy::SetSupportedTargetsForTest(target);
        for (int bitDepth : {8, 16}) {
            for (bool withAlpha : {false, true}) {
                const size_t pixelBytes = (withAlpha ? 4 : 3) * size_t(bitDepth / 8);
                for (size_t pixels :
                     {size_t(1), size_t(3), size_t(16), size_t(37), rgba.size() / 4}) {
                    const std::vector<float> part(rgba.end() - 4 * pixels, rgba.end());
                    // One byte more, which must stay as it was.
                    std::vector<uint8_t> samples(pixels * pixelBytes + 1, 0xa5);
                    quantisePngSamples(part.data(), pixels, bitDepth, withAlpha, samples.data());
                    ASSERT_EQ(samples.back(), 0xa5) << hwy::TargetName(target);
                    samples.pop_back();
                    ASSERT_EQ(samples, samplesReference(part, bitDepth, withAlpha))
                        << hwy::TargetName(target) << ", " << bitDepth << " bits, " << pixels
                        << " pixels, alpha " << withAlpha;
                }
            }
        }

        std::uniform_int_distribution<int> byte(0, 255);
        for (size_t bytesPerPixel : {1, 2, 3, 4, 6, 8}) {
            for (size_t rowBytes :
                 {1, 2, 5, 8, 9, 15, 16, 17, 31, 33, 40, 63, 64, 65, 71, 100, 129, 1000, 5760}) {
                std::vector<uint8_t> row(rowBytes), previous(rowBytes);
                for (size_t i = 0; i < rowBytes; ++i) {
                    row[i] = uint8_t(byte(random));
                    previous[i] = uint8_t(byte(random));
                }
                std::vector<uint8_t> filtered(rowBytes + 1, 0xa5);
                filterPaethRow(row.data(), previous.data(), rowBytes, bytesPerPixel,
                               filtered.data());
                ASSERT_EQ(filtered.back(), 0xa5) << hwy::TargetName(target);
                filtered.pop_back();
                ASSERT_EQ(filtered, filterReference(row, previous, bytesPerPixel))
                    << hwy::TargetName(target) << ", " << bytesPerPixel << " bytes per pixel, "
                    << rowBytes << " bytes";
            }
        }
    }
    hwy::SetSupportedTargetsForTest(0);
}

// Every left (a), above (b) and upper left (c) byte: each pixel of four bytes after the first
// takes a and c from the pixel before it, in whose row and row above they are laid out.
TEST(PngLanes, PaethPredictsEveryTripleOfBytes) {
    std::vector<uint8_t> row, previous;
    for (int a = 0; a < 256; ++a) {
        for (int b = 0; b < 256; ++b) {
            for (int c = 0; c < 256; c += 4) {
                for (int k = 0; k < 4; ++k) {  // the pixel that holds a and c
                    row.push_back(uint8_t(a));
                    previous.push_back(uint8_t(c + k));
                }
                for (int k = 0; k < 4; ++k) {  // the pixel predicted
                    row.push_back(uint8_t(a ^ b ^ k));
                    previous.push_back(uint8_t(b));
                }
            }
        }
    }
    for (int64_t target : hwy::SupportedAndGeneratedTargets()) {
        hwy::SetSupportedTargetsForTest(target);
        std::vector<uint8_t> filtered(row.size());
        filterPaethRow(row.data(), previous.data(), row.size(), 4, filtered.data());
        ASSERT_EQ(filtered, filterReference(row, previous, 4)) << hwy::TargetName(target);
    }
    hwy::SetSupportedTargetsForTest(0);
}

// The opacity check says yes exactly when every alpha quantises to the largest sample, here
// with one pixel below it (or NaN) at each place, in runs of pixels of several lengths.
TEST(PngLanes, OpacityCheckAgreesWithTheQuantisedAlpha) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (int64_t target : hwy::SupportedAndGeneratedTargets()) {
        hwy::SetSupportedTargetsForTest(target);
        for (int bitDepth : {8, 16}) {
            const double maxValue = bitDepth == 8 ? 255.0 : 65535.0;
            auto quantiseAlpha = [&](float alpha) {
                return bitDepth == 8 ? quantiseReference<255>(alpha)
                                     : quantiseReference<65535>(alpha);
            };
            // The lowest alpha that still quantises to the maximum, and the float below it.
            float lowestOpaque = float((maxValue - 0.5) / maxValue);
            while (quantiseAlpha(lowestOpaque) < maxValue)
                lowestOpaque = std::nextafter(lowestOpaque, 2.0f);
            while (quantiseAlpha(std::nextafter(lowestOpaque, 0.0f)) == maxValue)
                lowestOpaque = std::nextafter(lowestOpaque, 0.0f);
            const float highestNot = std::nextafter(lowestOpaque, 0.0f);
            for (size_t pixels : {1, 7, 16, 33, 100}) {
                std::vector<float> rgba(4 * pixels, nan);  // colours do not matter
                for (size_t i = 0; i < pixels; ++i)
                    rgba[4 * i + 3] = i % 2 ? 1.0f : lowestOpaque;
                EXPECT_TRUE(allAlphaQuantiseToMax(rgba.data(), pixels, bitDepth))
                    << hwy::TargetName(target);
                for (size_t lower = 0; lower < pixels; ++lower) {
                    for (float alpha : {highestNot, 0.0f, nan}) {
                        std::vector<float> one = rgba;
                        one[4 * lower + 3] = alpha;
                        EXPECT_FALSE(allAlphaQuantiseToMax(one.data(), pixels, bitDepth))
                            << hwy::TargetName(target) << ", " << bitDepth << " bits, pixel "
                            << lower << " of " << pixels << ", alpha " << alpha;
                    }
                }
            }
        }
    }
    hwy::SetSupportedTargetsForTest(0);
}

// The checksum equals zlib's from any starting value, for every length up to a few chunks and
// for long runs (all 255 being the largest sums), on every target.
TEST(PngLanes, Adler32EqualsZlibs) {
    std::mt19937 random(3);
    std::vector<uint8_t> bytes(1 << 20);
    for (uint8_t& b : bytes)
        b = uint8_t(random());
    const std::vector<uint8_t> saturated(300000, 255);
    std::uniform_int_distribution<uint32_t> half(0, 65520);
    for (int64_t target : hwy::SupportedAndGeneratedTargets()) {
        hwy::SetSupportedTargetsForTest(target);
        for (size_t size = 0; size <= 300; ++size) {
            const uint32_t start = size % 3 == 0 ? 1 : half(random) << 16 | half(random);
            ASSERT_EQ(adler32Update(start, bytes.data() + size, size),
                      adler32_z(start, bytes.data() + size, size))
                << hwy::TargetName(target) << ", " << size << " bytes";
        }
        const uint32_t largest = 65520u << 16 | 65520u;
        ASSERT_EQ(adler32Update(largest, bytes.data(), bytes.size()),
                  adler32_z(largest, bytes.data(), bytes.size()))
            << hwy::TargetName(target);
        ASSERT_EQ(adler32Update(largest, saturated.data(), saturated.size()),
                  adler32_z(largest, saturated.data(), saturated.size()))
            << hwy::TargetName(target);
    }
    hwy::SetSupportedTargetsForTest(0);
}

}  // namespace
}  // namespace quaternia
