#include "quaternia/image/png_writer.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace quaternia {
namespace {

uint32_t readU32(const uint8_t* p) {
    return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | uint32_t(p[3]);
}

struct ParsedChunk {
    std::string type;
    std::vector<uint8_t> data;
};

// Splits a PNG into its chunks, checking the signature and every chunk's CRC on the way.
std::vector<ParsedChunk> parseChunks(const std::vector<uint8_t>& png) {
    const uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    EXPECT_TRUE(png.size() >= 8 && std::equal(signature, signature + 8, png.begin()));
    std::vector<ParsedChunk> chunks;
    size_t offset = 8;
    while (offset + 12 <= png.size()) {
        const uint32_t length = readU32(&png[offset]);
        if (offset + 12 + length > png.size()) {
            ADD_FAILURE() << "chunk overruns the file at " << offset;
            break;
        }
        const uint8_t* typeAndData = &png[offset + 4];
        EXPECT_EQ(readU32(typeAndData + 4 + length), uint32_t(crc32(0, typeAndData, 4 + length)))
            << "CRC of the chunk at " << offset;
        chunks.push_back({std::string(typeAndData, typeAndData + 4),
                          std::vector<uint8_t>(typeAndData + 4, typeAndData + 4 + length)});
        offset += 12 + length;
    }
    EXPECT_EQ(offset, png.size()) << "bytes after the last chunk";
    return chunks;
}

// PNG spec 9.4 as written there: p = a + b - c, the nearest of a, b, c, ties in that order.
uint8_t paeth(int a, int b, int c) {
    const int p = a + b - c;
    const int pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
    if (pa <= pb && pa <= pc) return uint8_t(a);
    if (pb <= pc) return uint8_t(b);
    return uint8_t(c);
}

std::vector<uint8_t> paethScanlines(const std::vector<uint8_t>& samples, size_t rowBytes,
                                    size_t bytesPerPixel) {
    std::vector<uint8_t> out;
    const size_t height = samples.size() / rowBytes;
    for (size_t y = 0; y < height; ++y) {
        out.push_back(4);
        for (size_t i = 0; i < rowBytes; ++i) {
            auto raw = [&](size_t row, size_t column) {
                return int(samples[row * rowBytes + column]);
            };
            const int a = i >= bytesPerPixel ? raw(y, i - bytesPerPixel) : 0;
            const int b = y > 0 ? raw(y - 1, i) : 0;
            const int c = y > 0 && i >= bytesPerPixel ? raw(y - 1, i - bytesPerPixel) : 0;
            out.push_back(uint8_t(raw(y, i) - paeth(a, b, c)));
        }
    }
    return out;
}

// Render-like bytes: smooth ramps, a patch of noise, so that deflate finds both matches and
// literals.
std::vector<uint8_t> testSamples(const PngFormat& format, unsigned seed) {
    std::mt19937 rng(seed);
    const size_t rowBytes = pngRowBytes(format);
    std::vector<uint8_t> samples(rowBytes * size_t(format.height));
    for (size_t y = 0; y < size_t(format.height); ++y) {
        for (size_t i = 0; i < rowBytes; ++i) {
            const bool noisy = (y / 64 + i / 256) % 3 == 0;
            samples[y * rowBytes + i] = noisy ? uint8_t(rng()) : uint8_t((i * 3 + y * 5) / 7);
        }
    }
    return samples;
}

TEST(PngWriter, SameBytesForAnyNumberOfThreads) {
    const PngFormat formats[] = {{640, 900, 8, PngColorType::Rgba},
                                 {640, 900, 8, PngColorType::Rgb},
                                 {333, 500, 16, PngColorType::Rgba},
                                 {1000, 300, 16, PngColorType::Gray}};
    for (const PngFormat& format : formats) {
        SCOPED_TRACE(std::to_string(format.width) + "x" + std::to_string(format.height));
        const std::vector<uint8_t> samples = testSamples(format, 3);
        const std::vector<uint8_t> one = writePngBytes(format, samples, 1);
        EXPECT_EQ(writePngBytes(format, samples, 2), one);
        EXPECT_EQ(writePngBytes(format, samples, 8), one);
        EXPECT_EQ(writePngBytes(format, samples, 0), one);
    }
}

// Rows made on demand into the writer's scratch row (as encodePng quantises them) give the bytes
// of the same rows handed over whole, and the source is asked only for rows that exist.
TEST(PngWriter, RowsMadeOnDemandGiveTheSameBytes) {
    const PngFormat format{640, 900, 8, PngColorType::Rgb};
    const std::vector<uint8_t> samples = testSamples(format, 4);
    const size_t rowBytes = pngRowBytes(format);
    std::atomic<size_t> calls{0}, outside{0};
    const std::vector<uint8_t> made = writePngRows(
        format,
        [&](size_t y, uint8_t* scratch) {
            ++calls;
            if (y >= size_t(format.height)) {
                ++outside;
                y = 0;
            }
            std::copy_n(samples.data() + y * rowBytes, rowBytes, scratch);
            return static_cast<const uint8_t*>(scratch);
        },
        2);
    EXPECT_EQ(made, writePngBytes(format, samples, 1));
    EXPECT_EQ(outside.load(), 0u);
    EXPECT_GE(calls.load(), size_t(format.height));
}

// Signature, IHDR, several IDAT chunks (one per piece) whose data is one zlib stream of the
// Paeth-filtered rows, IEND; every CRC right, and zlib's uncompress checks the Adler-32.
TEST(PngWriter, WritesChunksOfOneZlibStreamOfPaethRows) {
    const PngFormat format{500, 700, 8, PngColorType::Rgba};  // 2001 bytes a row: 6 pieces
    const std::vector<uint8_t> samples = testSamples(format, 5);
    const std::vector<ParsedChunk> chunks = parseChunks(writePngBytes(format, samples, 2));
    ASSERT_GE(chunks.size(), 4u);
    EXPECT_EQ(chunks.front().type, "IHDR");
    EXPECT_EQ(chunks.front().data,
              (std::vector<uint8_t>{0, 0, 1, 0xf4, 0, 0, 2, 0xbc, 8, 6, 0, 0, 0}));
    EXPECT_EQ(chunks.back().type, "IEND");
    EXPECT_TRUE(chunks.back().data.empty());

    std::vector<uint8_t> stream;
    size_t idatChunks = 0;
    for (size_t i = 1; i + 1 < chunks.size(); ++i) {
        EXPECT_EQ(chunks[i].type, "IDAT");
        stream.insert(stream.end(), chunks[i].data.begin(), chunks[i].data.end());
        ++idatChunks;
    }
    EXPECT_EQ(idatChunks, 6u);
    const std::vector<uint8_t> expected = paethScanlines(samples, pngRowBytes(format), 4);
    std::vector<uint8_t> inflated(expected.size() + 1);
    uLongf inflatedSize = uLongf(inflated.size());
    ASSERT_EQ(uncompress(inflated.data(), &inflatedSize, stream.data(), uLong(stream.size())),
              Z_OK);
    inflated.resize(inflatedSize);
    EXPECT_TRUE(inflated == expected) << "the filtered rows";
    // Primed pieces compress nearly as well as one stream: within 2% of the whole filtered image
    // deflated at once with the writer's settings (level 1, run-length matches).
    z_stream whole{};
    ASSERT_EQ(deflateInit2(&whole, 1, Z_DEFLATED, 15, 8, Z_RLE), Z_OK);
    std::vector<uint8_t> wholeBytes(deflateBound(&whole, uLong(expected.size())));
    whole.next_in = const_cast<Bytef*>(expected.data());
    whole.avail_in = uInt(expected.size());
    whole.next_out = wholeBytes.data();
    whole.avail_out = uInt(wholeBytes.size());
    ASSERT_EQ(deflate(&whole, Z_FINISH), Z_STREAM_END);
    const double wholeSize = double(whole.total_out);
    deflateEnd(&whole);
    EXPECT_LT(double(stream.size()), 1.02 * wholeSize);
}

TEST(PngWriter, SixteenBitPixelsPredictFromTheirOwnBytes) {
    // Two bytes a sample, eight a pixel: a = the same byte of the pixel to the left.
    const PngFormat format{3, 2, 16, PngColorType::Rgba};
    const std::vector<uint8_t> samples = testSamples(format, 9);
    const std::vector<ParsedChunk> chunks = parseChunks(writePngBytes(format, samples));
    ASSERT_EQ(chunks.size(), 3u) << "a small image is one piece";
    const std::vector<uint8_t> expected = paethScanlines(samples, 24, 8);
    std::vector<uint8_t> inflated(expected.size());
    uLongf inflatedSize = uLongf(inflated.size());
    ASSERT_EQ(uncompress(inflated.data(), &inflatedSize, chunks[1].data.data(),
                         uLong(chunks[1].data.size())),
              Z_OK);
    EXPECT_EQ(inflated, expected);
}

TEST(PngWriter, RejectsEmptyImagesOtherDepthsAndWrongSampleCounts) {
    const std::vector<uint8_t> samples(12);
    EXPECT_THROW(writePngBytes({0, 1, 8, PngColorType::Rgba}, {}), std::invalid_argument);
    EXPECT_THROW(writePngBytes({1, 3, 4, PngColorType::Rgba}, samples), std::invalid_argument);
    EXPECT_THROW(writePngBytes({1, 2, 8, PngColorType::Rgba}, samples), std::invalid_argument);
    EXPECT_NO_THROW(writePngBytes({1, 3, 8, PngColorType::Rgba}, samples));
    EXPECT_NO_THROW(writePngBytes({2, 2, 8, PngColorType::Rgb}, samples));
}

}  // namespace
}  // namespace quaternia
