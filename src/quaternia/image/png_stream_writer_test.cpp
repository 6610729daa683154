#include "quaternia/image/png_stream_writer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "quaternia/image/png_io.h"
#include "quaternia/image/png_writer.h"
#include "quaternia/util/test_scratch_path.h"

namespace quaternia {
namespace {

// Samples that the encoder compresses in both ways: flat stretches (long runs) between noise.
std::vector<uint8_t> testSamples(const PngFormat& format, unsigned seed) {
    std::vector<uint8_t> samples(pngRowBytes(format) * size_t(format.height));
    std::mt19937 random(seed);
    for (size_t i = 0; i < samples.size(); ++i)
        samples[i] = (i / 997) % 3 == 0 ? uint8_t(i / 4096) : uint8_t(random());
    return samples;
}

// PNG spec 9.4: the nearest of a, b, c to a + b - c, ties in that order.
uint8_t paeth(int a, int b, int c) {
    const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
    return uint8_t(pa <= pb && pa <= pc ? a : pb <= pc ? b : c);
}

// testSamples changed so that every scanline, filtered, ends and starts with a run of the
// filter byte 4 (the first pixel's residuals are 4, and the last byte's): a piece's encoding
// then depends on the last filtered byte of the row before it, which needs the row above that.
std::vector<uint8_t> seamSamples(const PngFormat& format, unsigned seed) {
    std::vector<uint8_t> samples = testSamples(format, seed);
    const size_t rowBytes = pngRowBytes(format);
    const size_t pixel = rowBytes / size_t(format.width), last = rowBytes - 1;
    for (size_t y = 0; y < size_t(format.height); ++y) {
        uint8_t* row = samples.data() + y * rowBytes;
        const uint8_t* up = y > 0 ? row - rowBytes : nullptr;
        for (size_t i = 0; i < std::min<size_t>(pixel, 2); ++i)
            row[i] = uint8_t((up ? up[i] : 0) + 4);
        const int a = last >= pixel ? row[last - pixel] : 0;
        const int c = up && last >= pixel ? up[last - pixel] : 0;
        row[last] = uint8_t(paeth(a, up ? up[last] : 0, c) + 4);
    }
    return samples;
}

// The file a PngStreamWriter writes when handed the rows `chunkRows` at a time (the last chunk
// shorter), each chunk from a buffer that is overwritten once the call returns: the writer must
// have kept what it needs.
std::vector<uint8_t> streamPng(const PngFormat& format, const std::vector<uint8_t>& samples,
                               size_t chunkRows, int threads) {
    std::vector<uint8_t> file;
    PngStreamWriter writer(
        format,
        [&](std::span<const uint8_t> bytes) {
            file.insert(file.end(), bytes.begin(), bytes.end());
        },
        threads);
    const size_t rowBytes = pngRowBytes(format), height = size_t(format.height);
    std::vector<uint8_t> buffer;
    for (size_t y = 0; y < height; y += chunkRows) {
        const size_t count = std::min(chunkRows, height - y);
        buffer.assign(samples.begin() + std::ptrdiff_t(y * rowBytes),
                      samples.begin() + std::ptrdiff_t((y + count) * rowBytes));
        writer.addRows(buffer, count);
        std::fill(buffer.begin(), buffer.end(), uint8_t(0xa5));
        writer.addRows({}, 0);  // nothing, harmlessly
    }
    EXPECT_EQ(writer.rowsAdded(), height);
    writer.finish();
    return file;
}

TEST(PngStreamWriter, WritesTheBytesOfWritePngBytesWhateverTheChunksAndThreads) {
    const PngFormat formats[] = {
        {100, 2000, 8, PngColorType::Rgb},    // 870-row pieces, the last one shorter
        {33000, 5, 16, PngColorType::Rgba},   // rows over 256 KiB: a piece per row
        {1000, 300, 16, PngColorType::Gray},  // 131-row pieces, the last one shorter
        {17, 1, 8, PngColorType::Rgba},       // one row
        {7, 3, 16, PngColorType::Rgb},
    };
    unsigned seed = 1;
    for (const PngFormat& format : formats) {
        for (bool seams : {false, true}) {
            const std::vector<uint8_t> samples =
                seams ? seamSamples(format, seed) : testSamples(format, seed);
            const std::vector<uint8_t> expected = writePngBytes(format, samples, 1);
            for (size_t chunkRows : {size_t(1), size_t(7), size_t(format.height)})
                for (int threads : {1, 3})
                    EXPECT_TRUE(streamPng(format, samples, chunkRows, threads) == expected)
                        << format.width << "x" << format.height << (seams ? " with seams" : "")
                        << " in chunks of " << chunkRows << " rows on " << threads << " threads";
        }
        ++seed;
    }
}

TEST(PngStreamWriter, WritesEachPieceBeforeTheRowsAfterIt) {
    const PngFormat format{1000, 300, 16, PngColorType::Gray};  // 131 rows a piece
    const std::vector<uint8_t> samples = testSamples(format, 7);
    const std::vector<uint8_t> expected = writePngBytes(format, samples);
    std::vector<uint8_t> file;
    PngStreamWriter writer(format, [&](std::span<const uint8_t> bytes) {
        file.insert(file.end(), bytes.begin(), bytes.end());
    });
    EXPECT_EQ(file.size(), 8u + 25u);  // signature and IHDR at once
    const size_t rowBytes = pngRowBytes(format);
    writer.addRows(std::span(samples).first(130 * rowBytes), 130);
    EXPECT_EQ(file.size(), 8u + 25u);  // the first piece lacks a row
    writer.addRows(std::span(samples).subspan(130 * rowBytes, rowBytes), 1);
    ASSERT_GT(file.size(), 8u + 25u);  // its IDAT chunk, with 169 rows still to come
    EXPECT_TRUE(std::equal(file.begin(), file.end(), expected.begin()));
    writer.addRows(std::span(samples).subspan(131 * rowBytes), 169);
    writer.finish();
    EXPECT_TRUE(file == expected);
}

TEST(PngStreamWriter, RefusesWrongRowsAndAnUnfinishedImage) {
    const PngFormat format{4, 3, 8, PngColorType::Rgb};
    const auto ignore = [](std::span<const uint8_t>) {};
    EXPECT_THROW(PngStreamWriter({0, 3, 8, PngColorType::Rgb}, ignore), std::invalid_argument);
    EXPECT_THROW(PngStreamWriter({4, 3, 12, PngColorType::Rgb}, ignore), std::invalid_argument);

    PngStreamWriter writer(format, ignore);
    const std::vector<uint8_t> rows(4 * 12, 0);
    EXPECT_THROW(writer.addRows(std::span(rows).first(13), 1), std::invalid_argument);
    EXPECT_THROW(writer.addRows(rows, 4), std::invalid_argument);  // one row too many
    writer.addRows(std::span(rows).first(24), 2);
    EXPECT_THROW(writer.finish(), std::logic_error);  // a row missing
    EXPECT_THROW(writer.addRows(std::span(rows).first(24), 2), std::invalid_argument);
    writer.addRows(std::span(rows).first(12), 1);
    EXPECT_EQ(writer.rowsAdded(), 3u);
    writer.finish();
    EXPECT_THROW(writer.finish(), std::logic_error);
}

// A file in the test's temporary folder, removed at the end.
struct TempFile {
    std::string path = quaternia::testing::scratchPath(
                           std::string("quaternia_png_rows_") +
                           ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".png")
                           .string();
    ~TempFile() { std::filesystem::remove(path); }
    void write(const std::vector<uint8_t>& bytes, size_t size) const {
        FILE* file = std::fopen(path.c_str(), "wb");
        ASSERT_NE(file, nullptr);
        ASSERT_EQ(std::fwrite(bytes.data(), 1, size, file), size);
        std::fclose(file);
    }
};

TEST(PngRowReader, ReadsBackTheSamplesAsStored) {
    for (const PngFormat format :
         {PngFormat{300, 1000, 8, PngColorType::Rgba}, PngFormat{5, 4, 16, PngColorType::Rgb}}) {
        const std::vector<uint8_t> samples = testSamples(format, 11);
        TempFile file;
        const std::vector<uint8_t> png = writePngBytes(format, samples);
        file.write(png, png.size());
        PngRowReader reader(file.path);
        EXPECT_EQ(reader.format().width, format.width);
        EXPECT_EQ(reader.format().height, format.height);
        EXPECT_EQ(reader.format().bitDepth, format.bitDepth);
        EXPECT_EQ(reader.format().colorType, format.colorType);
        const size_t rowBytes = pngRowBytes(format);
        std::vector<uint8_t> row(rowBytes), read;
        for (int y = 0; y < format.height; ++y) {
            reader.readRow(row);
            read.insert(read.end(), row.begin(), row.end());
        }
        EXPECT_EQ(reader.rowsRead(), size_t(format.height));
        EXPECT_TRUE(read == samples);
        EXPECT_THROW(reader.readRow(row), std::runtime_error);
    }
}

TEST(PngRowReader, ReportsMissingAndTruncatedFiles) {
    TempFile file;
    EXPECT_THROW(PngRowReader(file.path + ".none"), std::runtime_error);
    const PngFormat format{300, 1000, 8, PngColorType::Rgba};
    const std::vector<uint8_t> png = writePngBytes(format, testSamples(format, 3));
    file.write(png, png.size() / 2);
    PngRowReader reader(file.path);
    std::vector<uint8_t> row(pngRowBytes(format));
    EXPECT_THROW(for (int y = 0; y < format.height; ++y) reader.readRow(row), std::runtime_error);
    EXPECT_THROW(reader.readRow(std::span(row).first(3)), std::runtime_error);
}

}  // namespace
}  // namespace quaternia
