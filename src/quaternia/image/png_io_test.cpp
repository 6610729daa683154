#include "quaternia/image/png_io.h"

#include <gtest/gtest.h>
#include <stdlib.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "quaternia/image/mask_compare.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

namespace fs = std::filesystem;

// ---- a tiny independent PNG writer (stored deflate blocks), to feed the reader every
// colour type and bit depth without going through libpng's writer ---------------------------

uint32_t crc32(const uint8_t* data, size_t size, uint32_t crc = 0) {
    crc = ~crc;
    for (size_t i = 0; i < size; ++i) {
        crc ^= data[i];
        for (int k = 0; k < 8; ++k)
            crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

void putU32(std::vector<uint8_t>& out, uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8)
        out.push_back(uint8_t(v >> shift));
}

void putChunk(std::vector<uint8_t>& png, const char* type, const std::vector<uint8_t>& data) {
    putU32(png, uint32_t(data.size()));
    std::vector<uint8_t> body(type, type + 4);
    body.insert(body.end(), data.begin(), data.end());
    png.insert(png.end(), body.begin(), body.end());
    putU32(png, crc32(body.data(), body.size()));
}

std::vector<uint8_t> zlibStored(const std::vector<uint8_t>& raw) {
    std::vector<uint8_t> z{0x78, 0x01};
    size_t offset = 0;
    do {
        const size_t n = std::min<size_t>(raw.size() - offset, 65535);
        const bool last = offset + n == raw.size();
        z.push_back(last ? 1 : 0);
        z.push_back(uint8_t(n & 0xff));
        z.push_back(uint8_t(n >> 8));
        z.push_back(uint8_t(~n & 0xff));
        z.push_back(uint8_t((~n >> 8) & 0xff));
        z.insert(z.end(), raw.begin() + long(offset), raw.begin() + long(offset + n));
        offset += n;
    } while (offset < raw.size());
    uint32_t a = 1, b = 0;
    for (uint8_t byte : raw) {
        a = (a + byte) % 65521;
        b = (b + a) % 65521;
    }
    putU32(z, (b << 16) | a);
    return z;
}

struct Chunk {
    const char* type;
    std::vector<uint8_t> data;
};

// `scanlines` are the filtered rows as PNG stores them (each with its filter byte first).
std::vector<uint8_t> makePng(uint32_t width, uint32_t height, uint8_t bitDepth, uint8_t colorType,
                             const std::vector<uint8_t>& scanlines,
                             const std::vector<Chunk>& beforeData = {}, uint8_t interlace = 0) {
    std::vector<uint8_t> png{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    std::vector<uint8_t> header;
    putU32(header, width);
    putU32(header, height);
    header.insert(header.end(), {bitDepth, colorType, 0, 0, interlace});
    putChunk(png, "IHDR", header);
    for (const Chunk& chunk : beforeData)
        putChunk(png, chunk.type, chunk.data);
    putChunk(png, "IDAT", zlibStored(scanlines));
    putChunk(png, "IEND", {});
    return png;
}

// ---- helpers ---------------------------------------------------------------------------

std::string makeTempDirectory() {
    std::string pattern = ::testing::TempDir() + "quaternia_png_XXXXXX";
    if (!::mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
    return pattern;
}

std::vector<uint8_t> fileBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void expectPixel(const Image& image, int x, int y, Rgba expected) {
    SCOPED_TRACE("pixel (" + std::to_string(x) + ", " + std::to_string(y) + ")");
    const Rgba& p = image.at(x, y);
    EXPECT_EQ(p.r, expected.r);
    EXPECT_EQ(p.g, expected.g);
    EXPECT_EQ(p.b, expected.b);
    EXPECT_EQ(p.a, expected.a);
}

float q8(int v) {
    return float(v) / 255.0f;
}
float q16(int v) {
    return float(v) / 65535.0f;
}

// ---- encoding ----------------------------------------------------------------------------

TEST(PngIo, EncodesRgbaHeaderAtEightAndSixteenBits) {
    Image image(3, 2);
    for (int bits : {8, 16}) {
        std::vector<uint8_t> png = encodePng(image, bits);
        ASSERT_GT(png.size(), 33u);
        EXPECT_EQ(std::vector<uint8_t>(png.begin(), png.begin() + 8),
                  (std::vector<uint8_t>{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'}));
        EXPECT_EQ(std::string(png.begin() + 12, png.begin() + 16), "IHDR");
        EXPECT_EQ(png[19], 3) << "width";
        EXPECT_EQ(png[23], 2) << "height";
        EXPECT_EQ(png[24], bits) << "bit depth";
        EXPECT_EQ(png[25], 6) << "colour type RGBA";
    }
}

TEST(PngIo, RejectsOtherBitDepthsAndEmptyImages) {
    Image image(2, 2);
    EXPECT_THROW(encodePng(image, 4), std::invalid_argument);
    EXPECT_THROW(encodePng(image, 32), std::invalid_argument);
    EXPECT_THROW(encodePng(Image(), 8), std::invalid_argument);
    EXPECT_THROW(encodePng(Image(0, 3), 16), std::invalid_argument);
    EXPECT_THROW(encodeGrayPng16(GrayImage()), std::invalid_argument);
}

TEST(PngIo, RoundTripsEightBitAfterQuantisation) {
    Image image(4, 2);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    image.at(0, 0) = Rgba{0.0f, 1.0f, 0.5f, 0.2f};
    image.at(1, 0) = Rgba{-0.3f, 1.7f, nan, 1.0f};
    image.at(2, 0) = Rgba{0.001f, 0.002f, 0.998f, 0.999f};
    image.at(3, 1) = Rgba{0.25f, 0.75f, 0.123456f, 0.0f};
    Image decoded = decodePng(encodePng(image, 8));
    ASSERT_EQ(decoded.width(), 4);
    ASSERT_EQ(decoded.height(), 2);
    expectPixel(decoded, 0, 0, {q8(0), q8(255), q8(128), q8(51)});
    expectPixel(decoded, 1, 0, {q8(0), q8(255), q8(0), q8(255)});  // clamped; NaN is 0
    expectPixel(decoded, 2, 0, {q8(0), q8(1), q8(254), q8(255)});
    expectPixel(decoded, 3, 1, {q8(64), q8(191), q8(31), q8(0)});
    expectPixel(decoded, 0, 1, {0, 0, 0, 0});
}

TEST(PngIo, RoundTripsSixteenBitAfterQuantisation) {
    Image image(2, 2);
    image.at(0, 0) = Rgba{0.5f, 0.2f, 0.123456f, 1.0f};
    image.at(1, 0) = Rgba{1e-5f, 2e-5f, 0.99999f, 0.7f};
    image.at(1, 1) = Rgba{-1.0f, 2.0f, 0.25f, 0.0f};
    Image decoded = decodePng(encodePng(image, 16));
    expectPixel(decoded, 0, 0, {q16(32768), q16(13107), q16(8091), q16(65535)});
    // 0.7f is 0.69999999, and 0.69999999 * 65535 = 45874.4993: rounds down.
    expectPixel(decoded, 1, 0, {q16(1), q16(1), q16(65534), q16(45874)});
    expectPixel(decoded, 1, 1, {q16(0), q16(65535), q16(16384), q16(0)});
}

// Every 8- and 16-bit level comes back as exactly the float it was written from.
TEST(PngIo, EveryQuantisedLevelRoundTripsExactly) {
    Image levels(256, 256);
    for (int y = 0; y < 256; ++y) {
        for (int x = 0; x < 256; ++x) {
            const int v = y * 256 + x;
            levels.at(x, y) = Rgba{q16(v), q16(65535 - v), q8(x), q8(y)};
        }
    }
    Image decoded = decodePng(encodePng(levels, 16));
    ASSERT_EQ(decoded.pixels().size(), levels.pixels().size());
    EXPECT_TRUE(decoded.pixels() == levels.pixels());

    Image bytes(256, 1);
    for (int x = 0; x < 256; ++x)
        bytes.at(x, 0) = Rgba{q8(x), q8(255 - x), q8(x / 2), q8(x)};
    EXPECT_TRUE(decodePng(encodePng(bytes, 8)).pixels() == bytes.pixels());
}

TEST(PngIo, AlphaIsPreservedIndependentlyOfColour) {
    Image image(3, 1);
    image.at(0, 0) = Rgba{1, 1, 1, 0};  // not premultiplied: colour survives zero alpha
    image.at(1, 0) = Rgba{0.2f, 0.4f, 0.6f, 0.5f};
    image.at(2, 0) = Rgba{0, 0, 0, 1};
    for (int bits : {8, 16}) {
        Image decoded = decodePng(encodePng(image, bits));
        const float half = bits == 8 ? q8(128) : q16(32768);
        EXPECT_EQ(decoded.at(0, 0), (Rgba{1, 1, 1, 0})) << bits;
        EXPECT_EQ(decoded.at(1, 0).a, half) << bits;
        EXPECT_EQ(decoded.at(2, 0).a, 1.0f) << bits;
    }
}

TEST(PngIo, GrayDepthSixteenBitRoundTrips) {
    GrayImage depth(3, 2);
    depth.at(0, 0) = 0.0f;
    depth.at(1, 0) = 1.0f;
    depth.at(2, 0) = 0.5f;
    depth.at(0, 1) = 0.3f;
    depth.at(1, 1) = 1.5f;
    depth.at(2, 1) = q16(12345);
    std::vector<uint8_t> png = encodeGrayPng16(depth);
    EXPECT_EQ(png[24], 16) << "bit depth";
    EXPECT_EQ(png[25], 0) << "colour type gray";
    Image decoded = decodePng(png);
    const int expected[6] = {0, 65535, 32768, 19661, 65535, 12345};
    for (int i = 0; i < 6; ++i) {
        const float v = q16(expected[i]);
        expectPixel(decoded, i % 3, i / 3, {v, v, v, 1.0f});
    }
}

// ---- the writer through libpng's reader --------------------------------------------------

// The documented rounding, written out again: clamp to [0, 1] (NaN to 0), floor(v * max + 0.5),
// then the level as the decoder returns it (level / max, correctly rounded to float).
float quantised(float v, int bits) {
    const int maxValue = bits == 8 ? 255 : 65535;
    if (!(v > 0.0f)) return 0.0f;
    if (v >= 1.0f) return 1.0f;
    const int level = int(std::floor(double(v) * maxValue + 0.5));
    return bits == 8 ? q8(level) : q16(level);
}

// Smooth gradients with noise on top, some values outside [0, 1]; alpha all 1 when opaque,
// else anything from 0 to 1.
Image testImage(int width, int height, bool opaque, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> noise(-0.05f, 0.05f);
    std::uniform_real_distribution<float> alpha(0.0f, 1.0f);
    Image image(width, height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const float u = float(x) / float(width), v = float(y) / float(height);
            image.at(x, y) = Rgba{u + noise(rng), v + noise(rng), 1.02f * (u * v) + noise(rng),
                                  opaque ? 1.0f : alpha(rng)};
        }
    }
    return image;
}

TEST(PngIo, RoundTripsEverySizeDepthAndAlphaExactly) {
    // 100 x 3000 crosses several of the writer's pieces (about 256 KiB of filtered rows each).
    const int sizes[][2] = {{1, 1}, {3, 7}, {257, 129}, {100, 3000}};
    unsigned seed = 1;
    for (const auto& size : sizes) {
        for (int bits : {8, 16}) {
            for (bool opaque : {false, true}) {
                SCOPED_TRACE(std::to_string(size[0]) + "x" + std::to_string(size[1]) + ", " +
                             std::to_string(bits) + " bits, " + (opaque ? "opaque" : "alpha"));
                Image image = testImage(size[0], size[1], opaque, seed++);
                std::vector<uint8_t> png = encodePng(image, bits);
                // A caller that knows the image is opaque gets the same file without the check.
                if (opaque) {
                    EXPECT_EQ(encodePng(image, bits, /*opaque=*/true), png);
                }
                ASSERT_GT(png.size(), 33u);
                EXPECT_EQ(png[24], bits) << "bit depth";
                EXPECT_EQ(png[25], opaque ? 2 : 6) << "colour type";
                Image decoded = decodePng(png);
                ASSERT_EQ(decoded.width(), size[0]);
                ASSERT_EQ(decoded.height(), size[1]);
                int mismatches = 0;
                for (size_t i = 0; i < image.pixels().size(); ++i) {
                    const Rgba& in = image.pixels()[i];
                    const Rgba expected{quantised(in.r, bits), quantised(in.g, bits),
                                        quantised(in.b, bits), quantised(in.a, bits)};
                    if (decoded.pixels()[i] != expected && mismatches++ < 5)
                        ADD_FAILURE() << "pixel " << i;
                }
                EXPECT_EQ(mismatches, 0);
            }
        }
    }
}

// Opaque means every alpha rounds to the maximum at the chosen depth: 0.999 is 255 at 8 bits
// but 65469 at 16.
TEST(PngIo, AlphaThatRoundsToTheMaximumCountsAsOpaque) {
    Image image(2, 2);
    for (int y = 0; y < 2; ++y) {
        for (int x = 0; x < 2; ++x)
            image.at(x, y) = Rgba{0.25f, 0.5f, 0.75f, x + y == 0 ? 0.999f : 1.0f};
    }
    std::vector<uint8_t> eight = encodePng(image, 8);
    EXPECT_EQ(eight[25], 2);
    EXPECT_EQ(decodePng(eight).at(0, 0), (Rgba{q8(64), q8(128), q8(191), 1.0f}));
    std::vector<uint8_t> sixteen = encodePng(image, 16);
    EXPECT_EQ(sixteen[25], 6);
    EXPECT_EQ(decodePng(sixteen).at(0, 0).a, q16(65469));

    image.at(1, 1).a = 0.99f;  // 252: not opaque even at 8 bits
    EXPECT_EQ(encodePng(image, 8)[25], 6);
}

TEST(PngIo, GrayDepthRoundTripsAcrossPieces) {
    GrayImage depth(300, 1000);  // 601 bytes a row: several pieces
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> value(-0.1f, 1.1f);
    for (int y = 0; y < depth.height(); ++y) {
        for (int x = 0; x < depth.width(); ++x)
            depth.at(x, y) = (x % 50 == 0) ? value(rng) : float(x + y) / 1300.0f;
    }
    Image decoded = decodePng(encodeGrayPng16(depth));
    int mismatches = 0;
    for (int y = 0; y < depth.height(); ++y) {
        for (int x = 0; x < depth.width(); ++x) {
            const float v = quantised(depth.at(x, y), 16);
            if (decoded.at(x, y) != Rgba{v, v, v, 1.0f} && mismatches++ < 5)
                ADD_FAILURE() << "pixel (" << x << ", " << y << ")";
        }
    }
    EXPECT_EQ(mismatches, 0);
}

// ---- decoding every kind of PNG --------------------------------------------------------

TEST(PngIo, DecodesGrayAtOneEightAndSixteenBits) {
    Image one = decodePng(makePng(8, 1, 1, 0, {0, 0b10100001}));
    const int bits[8] = {1, 0, 1, 0, 0, 0, 0, 1};
    for (int x = 0; x < 8; ++x) {
        const float v = float(bits[x]);
        expectPixel(one, x, 0, {v, v, v, 1});
    }
    Image eight = decodePng(makePng(2, 1, 8, 0, {0, 7, 200}));
    expectPixel(eight, 0, 0, {q8(7), q8(7), q8(7), 1});
    expectPixel(eight, 1, 0, {q8(200), q8(200), q8(200), 1});
    Image sixteen = decodePng(makePng(1, 2, 16, 0, {0, 0x12, 0x34, 0, 0xff, 0xfe}));
    expectPixel(sixteen, 0, 0, {q16(0x1234), q16(0x1234), q16(0x1234), 1});
    expectPixel(sixteen, 0, 1, {q16(0xfffe), q16(0xfffe), q16(0xfffe), 1});
}

TEST(PngIo, DecodesGrayAlphaAndRgbWithColourKey) {
    Image grayAlpha = decodePng(makePng(1, 1, 8, 4, {0, 100, 50}));
    expectPixel(grayAlpha, 0, 0, {q8(100), q8(100), q8(100), q8(50)});
    // tRNS on RGB: the colour (1, 2, 3) is transparent.
    Image keyed =
        decodePng(makePng(2, 1, 8, 2, {0, 10, 20, 30, 1, 2, 3}, {{"tRNS", {0, 1, 0, 2, 0, 3}}}));
    expectPixel(keyed, 0, 0, {q8(10), q8(20), q8(30), 1});
    expectPixel(keyed, 1, 0, {q8(1), q8(2), q8(3), 0});
    Image rgba16 = decodePng(makePng(1, 1, 16, 6, {0, 0, 1, 0x80, 0, 0xff, 0xff, 0x40, 0}));
    expectPixel(rgba16, 0, 0, {q16(1), q16(0x8000), q16(0xffff), q16(0x4000)});
}

TEST(PngIo, DecodesPalettesWithAndWithoutTransparency) {
    // 2-bit indices 0, 1, 2, 1; entry 0 is half transparent, the others opaque.
    Image image =
        decodePng(makePng(4, 1, 2, 3, {0, 0b00011001},
                          {{"PLTE", {255, 0, 0, 0, 255, 0, 0, 0, 255}}, {"tRNS", {128}}}));
    expectPixel(image, 0, 0, {1, 0, 0, q8(128)});
    expectPixel(image, 1, 0, {0, 1, 0, 1});
    expectPixel(image, 2, 0, {0, 0, 1, 1});
    expectPixel(image, 3, 0, {0, 1, 0, 1});

    // Without tRNS every entry is opaque; plain 8-bit RGB likewise.
    Image opaque = decodePng(makePng(2, 1, 8, 3, {0, 1, 0}, {{"PLTE", {10, 20, 30, 40, 50, 60}}}));
    expectPixel(opaque, 0, 0, {q8(40), q8(50), q8(60), 1});
    expectPixel(opaque, 1, 0, {q8(10), q8(20), q8(30), 1});
    Image rgb = decodePng(makePng(1, 1, 8, 2, {0, 70, 80, 90}));
    expectPixel(rgb, 0, 0, {q8(70), q8(80), q8(90), 1});
}

TEST(PngIo, DecodesInterlacedImages) {
    // Adam7 on 2 x 2: pass 1 holds (0, 0), pass 6 holds (1, 0), pass 7 holds row 1.
    Image image = decodePng(makePng(2, 2, 8, 0, {0, 10, 0, 20, 0, 30, 40}, {}, 1));
    expectPixel(image, 0, 0, {q8(10), q8(10), q8(10), 1});
    expectPixel(image, 1, 0, {q8(20), q8(20), q8(20), 1});
    expectPixel(image, 0, 1, {q8(30), q8(30), q8(30), 1});
    expectPixel(image, 1, 1, {q8(40), q8(40), q8(40), 1});
}

TEST(PngIo, MalformedDataThrowsWithTheReason) {
    EXPECT_THROW(decodePng(std::vector<uint8_t>{}), std::runtime_error);
    std::vector<uint8_t> notPng(100, 'x');
    EXPECT_THROW(decodePng(notPng), std::runtime_error);

    std::vector<uint8_t> png = encodePng(Image(16, 16), 8);
    std::vector<uint8_t> truncated(png.begin(), png.begin() + long(png.size() / 2));
    try {
        decodePng(truncated);
        FAIL() << "a truncated PNG decoded";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("truncated"), std::string::npos) << e.what();
    }
    std::vector<uint8_t> badCrc = png;
    badCrc[29] ^= 0xff;  // inside IHDR's CRC
    EXPECT_THROW(decodePng(badCrc), std::runtime_error);
}

// The ancillary chunks are skipped unread (png_read.cpp): malformed ones change nothing, and one
// that declares more bytes than the file holds ends as a truncated file, without libpng first
// allocating and clearing its declared 1.6 GB (found by fuzzing).
TEST(PngIo, SkipsAncillaryChunks) {
    const std::vector<Chunk> chunks = {{"gAMA", {1, 2}},
                                       {"tEXt", {'k', 0, 'v'}},
                                       {"zTXt", {'k', 0, 0, 0xff, 0xff}},
                                       {"PLTE", {10, 20, 30, 40, 50, 60}},
                                       {"tRNS", {128}}};
    Image image = decodePng(makePng(2, 1, 8, 3, {0, 1, 0}, chunks));
    expectPixel(image, 0, 0, {q8(40), q8(50), q8(60), 1});
    expectPixel(image, 1, 0, {q8(10), q8(20), q8(30), q8(128)});

    std::vector<uint8_t> png = makePng(2, 1, 8, 3, {0, 1, 0}, {{"PLTE", {10, 20, 30, 40, 50, 60}}});
    const std::vector<uint8_t> huge = {0x63, 0x89, 0x48, 0x00, 'z', 'T', 'X', 't', 'k', 0, 0};
    png.insert(png.begin() + 33, huge.begin(), huge.end());  // after IHDR
    try {
        decodePng(png);
        FAIL() << "a chunk longer than the file was read";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("truncated"), std::string::npos) << e.what();
    }
}

TEST(PngIo, RefusesHugeDimensionsBeforeAllocating) {
    EXPECT_THROW(decodePng(makePng(100000, 1, 8, 0, {0})), std::runtime_error);
    EXPECT_THROW(decodePng(makePng(30000, 30000, 8, 0, {0})), std::runtime_error);
}

// ---- files ---------------------------------------------------------------------------------

TEST(PngIo, WritesAndReadsFiles) {
    const std::string dir = makeTempDirectory();
    Image image(5, 3);
    image.at(4, 2) = Rgba{0.5f, 0.25f, 1.0f, 0.75f};
    writePng(dir + "/image.png", image, 16);
    EXPECT_EQ(fileBytes(dir + "/image.png"), encodePng(image, 16));
    Image read = readPng(dir + "/image.png");
    expectPixel(read, 4, 2, {q16(32768), q16(16384), 1.0f, q16(49151)});

    GrayImage depth(2, 2);
    depth.at(1, 1) = 0.5f;
    writeGrayPng16(dir + "/depth.png", depth);
    EXPECT_EQ(readPng(dir + "/depth.png").at(1, 1).r, q16(32768));

    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 2)
        << "no temporaries left behind";
    fs::remove_all(dir);
}

TEST(PngIo, UnwritablePathIsAUserErrorNamingThePath) {
    const std::string path = makeTempDirectory() + "/missing/out.png";
    try {
        writePng(path, Image(2, 2), 8);
        FAIL() << "wrote into a missing directory";
    } catch (const UserError& e) {
        EXPECT_EQ(e.key(), path);
        EXPECT_EQ(std::string(e.what()), "cannot write '" + path + "': No such file or directory");
    }
    EXPECT_THROW(writeGrayPng16(path, GrayImage(1, 1)), UserError);
    fs::remove_all(fs::path(path).parent_path().parent_path());
}

TEST(PngIo, UnreadableFilesAreUserErrorsNamingThePath) {
    const std::string dir = makeTempDirectory();
    const std::string missing = dir + "/missing.png";
    try {
        readPng(missing);
        FAIL() << "read a missing file";
    } catch (const UserError& e) {
        EXPECT_EQ(e.key(), missing);
        EXPECT_EQ(std::string(e.what()),
                  "cannot read PNG '" + missing + "': No such file or directory");
    }
    const std::string text = dir + "/text.png";
    std::ofstream(text) << "this is not a PNG file";
    try {
        readPng(text);
        FAIL() << "read a text file";
    } catch (const UserError& e) {
        EXPECT_EQ(e.key(), text);
        EXPECT_EQ(std::string(e.what()).rfind("cannot read PNG '" + text + "': ", 0), 0u)
            << e.what();
    }
    EXPECT_THROW(readPng(dir), UserError) << "a directory";
    fs::remove_all(dir);
}

TEST(PngIo, ReadsAReferenceMask) {
    const std::string path =
        std::string(QUATERNIA_TEST_DATA_DIR) + "/reference/masks/case01_sqr_A_brute_320x240.png";
    Image image = readPng(path);
    ASSERT_EQ(image.width(), 320);
    ASSERT_EQ(image.height(), 240);
    expectPixel(image, 0, 0, {0, 0, 0, 1});
    expectPixel(image, 160, 120, {1, 1, 1, 1});
    Mask mask = maskFromImage(image);
    // Counted independently by decoding the file with Python's zlib.
    EXPECT_EQ(mask.count(), 20850);
    EXPECT_TRUE(mask.at(153, 25)) << "the first inside pixel in row-major order";
    EXPECT_FALSE(mask.at(152, 25));
    for (int y = 0; y < 25; ++y)
        EXPECT_FALSE(mask.at(153, y));
}

}  // namespace
}  // namespace quaternia
