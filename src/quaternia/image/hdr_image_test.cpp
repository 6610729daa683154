#include "quaternia/image/hdr_image.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfTiledOutputFile.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "quaternia/image/exr_writer.h"
#include "quaternia/util/error.h"
#include "quaternia/util/test_scratch_path.h"

namespace quaternia {
namespace {

const std::string kKey = "environment.map";
const MemoryBudget kUnlimited{};

std::vector<uint8_t> bytesOf(const std::string& text) {
    return std::vector<uint8_t>(text.begin(), text.end());
}

HdrImage decode(const std::vector<uint8_t>& bytes, const std::string& path = "sky.hdr") {
    return decodeHdrImage(bytes, path, kKey, kUnlimited);
}

// The UserError's message, checked to be one line naming the key and the file.
template <typename Error = UserError>
std::string errorOf(const std::vector<uint8_t>& bytes, const std::string& path = "sky.hdr",
                    const MemoryBudget& budget = kUnlimited) {
    try {
        decodeHdrImage(bytes, path, kKey, budget);
    } catch (const Error& error) {
        const std::string message = error.what();
        EXPECT_EQ(error.key(), kKey);
        EXPECT_NE(message.find(path), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        return message;
    }
    ADD_FAILURE() << "no error for " << path;
    return "";
}

HdrImage randomImage(int width, int height, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> unit(0, 1), power(-20, 20);
    HdrImage image{width, height, std::vector<float>(size_t(width) * height * 3)};
    for (size_t i = 0; i < image.rgb.size(); i += 3) {
        const float scale = std::exp2(power(random));
        for (int c = 0; c < 3; ++c)
            image.rgb[i + c] = unit(random) * scale;
        if (i % 7 == 0) image.rgb[i + 1] = image.rgb[i];  // some equal channels
    }
    std::fill(image.rgb.begin(), image.rgb.begin() + 3 * std::min(width, 12), 0.5f);  // a run
    return image;
}

void expectWithinRgbe(const HdrImage& expected, const HdrImage& actual) {
    ASSERT_EQ(actual.width, expected.width);
    ASSERT_EQ(actual.height, expected.height);
    ASSERT_EQ(actual.rgb.size(), expected.rgb.size());
    for (size_t i = 0; i < expected.rgb.size(); i += 3) {
        const float* e = &expected.rgb[i];
        const float* a = &actual.rgb[i];
        const int largest = int(std::max_element(e, e + 3) - e);
        ASSERT_LE(std::abs(a[largest] - e[largest]), e[largest] / 128) << "pixel " << i / 3;
        for (int c = 0; c < 3; ++c)
            ASSERT_LE(std::abs(a[c] - e[c]), e[largest] / 128) << "pixel " << i / 3;
    }
}

size_t headerSize(const std::vector<uint8_t>& file) {
    const std::string text(file.begin(), file.end());
    return text.find("+X ") + text.substr(text.find("+X ")).find('\n') + 1;
}

TEST(HdrImage, RadianceRoundTripRunLengthEncoded) {
    const HdrImage image = randomImage(64, 5, 1);
    const std::vector<uint8_t> file = encodeRadianceHdr(image);
    const size_t header = headerSize(file);
    ASSERT_GE(file.size(), header + 4);
    EXPECT_EQ(std::vector<uint8_t>(file.begin() + header, file.begin() + header + 4),
              (std::vector<uint8_t>{2, 2, 0, 64}));
    expectWithinRgbe(image, decode(file));
}

TEST(HdrImage, RadianceRoundTripFlat) {
    const HdrImage image = randomImage(4, 6, 2);
    const std::vector<uint8_t> file = encodeRadianceHdr(image);
    EXPECT_EQ(file.size(), headerSize(file) + 4 * 4 * 6);
    expectWithinRgbe(image, decode(file));
}

TEST(HdrImage, RadianceKnownBytesDecodeExactly) {
    // (m + 0.5) / 256 * 2^(e - 128): a flat file of two pixels, then one run-length encoded
    // scanline of 8 pixels (R: a run of 8; G: 8 literals; B: a run of 4, 4 literals; E: a run).
    std::vector<uint8_t> flat = bytesOf("#?RGBE\n# comment\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 2\n");
    flat.insert(flat.end(), {128, 64, 0, 129, 0, 0, 0, 0});
    const HdrImage a = decode(flat);
    EXPECT_EQ(a.rgb, (std::vector<float>{1.00390625f, 0.50390625f, 0.00390625f, 0, 0, 0}));

    std::vector<uint8_t> rle = bytesOf("#?RADIANCE\n\n-Y 1 +X 8\n");
    rle.insert(rle.end(),
               {2,       2, 0, 8,  128 + 8, 255, 8,  0,       1,      2, 3, 4, 5, 6, 7,  //
                128 + 4, 9, 4, 10, 11,      12,  13, 128 + 8, 128 + 2});
    const HdrImage b = decode(rle);
    ASSERT_EQ(b.rgb.size(), 24u);
    const float unit = 4.0f / 256;  // 2^(130 - 128) / 256
    const int blue[] = {9, 9, 9, 9, 10, 11, 12, 13};
    for (int x = 0; x < 8; ++x) {
        EXPECT_EQ(b.rgb[3 * x], 255.5f * unit);
        EXPECT_EQ(b.rgb[3 * x + 1], (x + 0.5f) * unit);
        EXPECT_EQ(b.rgb[3 * x + 2], (blue[x] + 0.5f) * unit);
    }
}

TEST(HdrImage, RadianceExposureLinesDivideTheValues) {
    std::vector<uint8_t> file =
        bytesOf("#?RADIANCE\nEXPOSURE=2\nEXPOSURE= 4.0 \nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 1\n");
    file.insert(file.end(), {128, 128, 128, 129});
    EXPECT_EQ(decode(file).rgb, std::vector<float>(3, 1.00390625f / 8));
    for (const char* bad : {"EXPOSURE=0", "EXPOSURE=-1", "EXPOSURE=abc"}) {
        std::vector<uint8_t> wrong = bytesOf("#?RADIANCE\n" + std::string(bad) + "\n\n-Y 1 +X 1\n");
        wrong.insert(wrong.end(), {128, 128, 128, 129});
        EXPECT_NE(errorOf(wrong).find("exposure"), std::string::npos);
    }
}

TEST(HdrImage, RadianceBadHeadersAndRunsAreRefused) {
    for (const char* line : {"+Y 1 +X 2", "-Y 1 -X 2", "-Y 0 +X 2", "-Y 1 +X 70000", "-Y abc +X 2",
                             "-Y 1 +X 2 extra", "-Y  1 +X 2", ""}) {
        std::vector<uint8_t> file = bytesOf("#?RADIANCE\n\n" + std::string(line) + "\n");
        file.resize(file.size() + 64, 128);
        const std::string message = errorOf(file);
        EXPECT_EQ(message.rfind(kKey + ": 'sky.hdr'", 0), 0u) << message;
    }
    std::vector<uint8_t> xyze = bytesOf("#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 1 +X 1\n");
    xyze.insert(xyze.end(), {128, 128, 128, 129});
    EXPECT_NE(errorOf(xyze).find("32-bit_rle_rgbe"), std::string::npos);
    // A run longer than the scanline, a literal of 0, a scanline marker of the wrong width.
    for (const std::vector<uint8_t>& pixels : std::vector<std::vector<uint8_t>>{
             {2, 2, 0, 8, 128 + 9, 1}, {2, 2, 0, 8, 0, 1}, {2, 2, 0, 9, 128 + 8, 1}}) {
        std::vector<uint8_t> file = bytesOf("#?RADIANCE\n\n-Y 1 +X 8\n");
        file.insert(file.end(), pixels.begin(), pixels.end());
        file.resize(file.size() + 40, 0);
        EXPECT_NE(errorOf(file).find("not a valid Radiance"), std::string::npos);
    }
}

TEST(HdrImage, RadianceEveryPrefixThrowsOrDecodes) {
    const std::vector<uint8_t> file = encodeRadianceHdr(randomImage(9, 3, 3));
    const std::vector<uint8_t> flat = encodeRadianceHdr(randomImage(3, 2, 4));
    for (const std::vector<uint8_t>* whole : {&file, &flat}) {
        for (size_t length = 0; length < whole->size(); ++length) {
            const std::vector<uint8_t> prefix(whole->begin(), whole->begin() + length);
            try {
                decode(prefix);
            } catch (const UserError& error) {
                EXPECT_EQ(std::string(error.what()).find('\n'), std::string::npos);
            }
        }
    }
    EXPECT_NE(errorOf(std::vector<uint8_t>(file.begin(), file.end() - 1)).find("truncated"),
              std::string::npos);
}

// An in-memory OStream, as exr_writer.cpp's, for a tiled file of half channels.
class MemoryOStream : public Imf::OStream {
  public:
    MemoryOStream() : Imf::OStream("memory") {}
    void write(const char c[], int n) override {
        if (position_ + size_t(n) > bytes.size()) bytes.resize(position_ + size_t(n));
        std::memcpy(bytes.data() + position_, c, size_t(n));
        position_ += size_t(n);
    }
    uint64_t tellp() override { return position_; }
    void seekp(uint64_t position) override { position_ = size_t(position); }
    std::vector<uint8_t> bytes;

  private:
    size_t position_ = 0;
};

TEST(HdrImage, ExrFloatChannelsReadExactly) {
    ExrImage exr{5, 3, {}};
    std::mt19937 random(5);
    std::uniform_real_distribution<float> value(0, 1000);
    for (const char* name : {"B", "G", "R", "A", "Z"}) {
        ExrChannel channel{name, std::vector<float>(15), {}};
        for (float& v : channel.values)
            v = value(random);
        exr.channels.push_back(channel);
    }
    exr.channels[0].values[0] = -1.0f;                                    // clamped to 0
    exr.channels[1].values[1] = std::numeric_limits<float>::quiet_NaN();  // clamped to 0
    const HdrImage image = decode(encodeExr(exr), "sky.exr");
    ASSERT_EQ(image.width, 5);
    ASSERT_EQ(image.height, 3);
    for (size_t i = 0; i < 15; ++i)
        for (int c = 0; c < 3; ++c) {
            const float expected = exr.channels[size_t(2 - c)].values[i];
            EXPECT_EQ(image.rgb[3 * i + size_t(c)], expected >= 0 ? expected : 0.0f);
        }
    EXPECT_EQ(image.rgb[2], 0.0f);
    EXPECT_EQ(image.rgb[4], 0.0f);

    const ExrImage grey{2, 1, {{"Y", {0.25f, 7.5f}, {}}}};
    EXPECT_EQ(decode(encodeExr(grey), "grey.exr").rgb,
              (std::vector<float>{0.25f, 0.25f, 0.25f, 7.5f, 7.5f, 7.5f}));
}

TEST(HdrImage, ExrTiledHalfWithADataWindow) {
    const Imath::Box2i display({0, 0}, {9, 9}), window({-2, 3}, {4, 4});  // 7 x 2
    Imf::Header header(display, window);
    header.setTileDescription(Imf::TileDescription(4, 4, Imf::ONE_LEVEL));
    std::vector<Imath::half> planes[3];
    Imf::FrameBuffer frame;
    for (int c = 0; c < 3; ++c) {
        const char* name = c == 0 ? "R" : c == 1 ? "G" : "B";
        for (int i = 0; i < 14; ++i)
            planes[c].push_back(Imath::half(float(i * 3 + c) / 4));
        header.channels().insert(name, Imf::Channel(Imf::HALF));
        frame.insert(name, Imf::Slice::Make(Imf::HALF, planes[c].data(), window));
    }
    MemoryOStream stream;
    {
        Imf::TiledOutputFile file(stream, header, 0);
        file.setFrameBuffer(frame);
        file.writeTiles(0, file.numXTiles() - 1, 0, file.numYTiles() - 1);
    }
    const HdrImage image = decode(stream.bytes, "tiled.exr");
    ASSERT_EQ(image.width, 7);
    ASSERT_EQ(image.height, 2);
    for (int i = 0; i < 42; ++i)
        EXPECT_EQ(image.rgb[size_t(i)], float(i) / 4);
}

TEST(HdrImage, ExrErrors) {
    const ExrImage depth{2, 2, {{"Z", std::vector<float>(4, 1.0f), {}}}};
    EXPECT_NE(errorOf(encodeExr(depth), "depth.exr").find("no R, G, B or Y channels (it has Z)"),
              std::string::npos);
    const std::vector<uint8_t> file = encodeExr({4, 4, {{"Y", std::vector<float>(16, 1.0f), {}}}});
    for (size_t length : {size_t(0), size_t(3), size_t(4), size_t(20), file.size() / 2,
                          file.size() - 8, file.size() - 1})
        errorOf(std::vector<uint8_t>(file.begin(), file.begin() + long(length)), "short.exr");
    EXPECT_NE(errorOf(std::vector<uint8_t>(file.begin(), file.begin() + 20), "short.exr")
                  .find("is truncated"),
              std::string::npos);
}

TEST(HdrImage, NotAnHdrImage) {
    const std::vector<uint8_t> png{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13};
    EXPECT_EQ(errorOf(png, "sky.png"),
              "environment.map: 'sky.png' is not an HDR image (Radiance .hdr or OpenEXR)");
    EXPECT_EQ(errorOf(bytesOf("#?RAD"), "sky.hdr"), "environment.map: 'sky.hdr' is truncated");
    try {  // a newline in the name does not break the message's line
        decode(bytesOf("#?RAD"), "a\nb.hdr");
        ADD_FAILURE();
    } catch (const UserError& error) {
        EXPECT_EQ(std::string(error.what()), "environment.map: 'a?b.hdr' is truncated");
    }
}

TEST(HdrImage, MemoryBudgetTooSmall) {
    const MemoryBudget small{1000, "--memory-budget"};
    const std::string message =
        errorOf<MemoryLimitError>(encodeRadianceHdr(randomImage(64, 64, 6)), "big.hdr", small);
    EXPECT_NE(message.find("--memory-budget"), std::string::npos);
    errorOf<MemoryLimitError>(encodeExr({64, 64, {{"Y", std::vector<float>(4096), {}}}}), "big.exr",
                              small);
    EXPECT_NO_THROW(decodeHdrImage(encodeRadianceHdr(randomImage(8, 8, 7)), "small.hdr", kKey,
                                   MemoryBudget{100000, "--memory-budget"}));
}

TEST(HdrImage, ReadsFilesAndNamesWhatIsWrong) {
    namespace fs = std::filesystem;
    const fs::path directory = testing::scratchPath("hdr_image_test");
    fs::create_directories(directory);
    const std::string path = (directory / "sky.hdr").string();
    const HdrImage image = randomImage(16, 2, 8);
    const std::vector<uint8_t> bytes = encodeRadianceHdr(image);
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    expectWithinRgbe(image, readHdrImage(path, kKey, kUnlimited));

    const auto messageOf = [](const std::string& file) {
        try {
            readHdrImage(file, kKey, kUnlimited);
        } catch (const UserError& error) {
            EXPECT_EQ(error.key(), kKey);
            return std::string(error.what());
        }
        return std::string("no error");
    };
    const std::string missing = (directory / "x.hdr").string();
    EXPECT_EQ(messageOf(missing), kKey + ": '" + missing + "': no such file");
    EXPECT_EQ(messageOf(directory.string()),
              kKey + ": '" + directory.string() + "': cannot read (is a directory)");
    if (::geteuid() != 0) {  // root reads whatever the mode says
        fs::permissions(path, fs::perms::none);
        EXPECT_EQ(messageOf(path), kKey + ": '" + path + "': cannot read (permission denied)");
        fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write);
    }
    EXPECT_THROW(encodeRadianceHdr(HdrImage{2, 2, std::vector<float>(11)}), std::invalid_argument);
    fs::remove_all(directory);
}

}  // namespace
}  // namespace quaternia
