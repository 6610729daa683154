// deflateRuns against zlib's inflate: every encoding decodes to its input, alone and as pieces
// of one stream, including inputs whose Huffman trees must be limited to 15 bits.
#include "quaternia/image/deflate_runs.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <random>
#include <string>
#include <vector>

namespace quaternia {
namespace {

std::vector<uint8_t> inflateRaw(const std::vector<uint8_t>& compressed, size_t expected) {
    z_stream stream{};
    EXPECT_EQ(inflateInit2(&stream, -15), Z_OK);
    std::vector<uint8_t> out(expected + 1);
    stream.next_in = const_cast<Bytef*>(compressed.data());
    stream.avail_in = uInt(compressed.size());
    stream.next_out = out.data();
    stream.avail_out = uInt(out.size());
    const int status = inflate(&stream, Z_FINISH);
    EXPECT_EQ(status, Z_STREAM_END) << (stream.msg ? stream.msg : "");
    EXPECT_EQ(stream.avail_in, 0u) << "bytes after the final block";
    out.resize(out.size() - stream.avail_out);
    inflateEnd(&stream);
    return out;
}

// The input cut into pieces at `cuts`, each encoded on its own and concatenated.
std::vector<uint8_t> encodeInPieces(const std::vector<uint8_t>& input, std::vector<size_t> cuts) {
    cuts.push_back(input.size());
    std::vector<uint8_t> stream;
    size_t begin = 0;
    for (size_t c = 0; c < cuts.size(); ++c) {
        const size_t end = cuts[c];
        std::vector<uint8_t> piece(deflateRunsBound(end - begin));
        const int before = begin > 0 ? input[begin - 1] : -1;
        const size_t written = deflateRuns(input.data() + begin, end - begin, before,
                                           c + 1 == cuts.size(), piece.data());
        EXPECT_LE(written, piece.size());
        stream.insert(stream.end(), piece.begin(), piece.begin() + std::ptrdiff_t(written));
        begin = end;
    }
    return stream;
}

void expectRoundTrip(const std::vector<uint8_t>& input, const std::string& what,
                     std::vector<size_t> cuts = {}) {
    const std::vector<uint8_t> stream = encodeInPieces(input, cuts);
    EXPECT_EQ(inflateRaw(stream, input.size()), input) << what;
}

TEST(DeflateRuns, EveryInputDecodesToItself) {
    std::mt19937 random(7);
    for (size_t size : {0, 1, 2, 3, 4, 100, 65534, 65535, 65536, 200000}) {
        std::vector<uint8_t> bytes(size);
        for (uint8_t& b : bytes)
            b = uint8_t(random());
        expectRoundTrip(bytes, "random bytes, " + std::to_string(size));
        expectRoundTrip(std::vector<uint8_t>(size, 0), "zeros, " + std::to_string(size));
        expectRoundTrip(std::vector<uint8_t>(size, 0xff), "0xff, " + std::to_string(size));
    }
    // Runs of every length around the codes' limits, of bytes equal and unequal to the last.
    std::vector<uint8_t> runs;
    for (int length = 1; length <= 600; ++length)
        runs.insert(runs.end(), size_t(length), uint8_t(length % 3 == 0 ? 7 : length));
    expectRoundTrip(runs, "runs of 1 to 600");
    // Small residuals with runs of zeros, as Paeth-filtered renders give.
    std::vector<uint8_t> residuals(300000);
    std::geometric_distribution<int> spread(0.6);
    for (size_t i = 0; i < residuals.size(); ++i) {
        const bool flat = (i / 5000) % 3 == 0;
        const int r = flat ? 0 : spread(random);
        residuals[i] = uint8_t(random() % 2 ? r : -r);
    }
    expectRoundTrip(residuals, "residuals");
}

TEST(DeflateRuns, PiecesMakeOneStream) {
    std::mt19937 random(11);
    std::vector<uint8_t> bytes(250000);
    for (size_t i = 0; i < bytes.size(); ++i)
        bytes[i] = (i / 1000) % 2 ? uint8_t(random() % 4) : 0;
    expectRoundTrip(bytes, "pieces", {1, 2, 3, 1000, 1001, 70000, 70000, 140000});
    // A run that goes on across a cut refers back into the piece before.
    std::vector<uint8_t> zeros(10000, 0);
    expectRoundTrip(zeros, "a run across cuts", {5000, 5001, 9999});
}

TEST(DeflateRuns, DeepTreesAreLimitedToFifteenBits) {
    // Fibonacci frequencies make Huffman's tree as deep as there are symbols (here 30): the
    // codes must be cut to 15 bits and stay complete.
    std::vector<uint8_t> bytes;
    uint64_t a = 1, b = 1;
    for (int symbol = 0; symbol < 30; ++symbol) {
        // Symbols alternate with a different byte between copies, so that nothing runs.
        for (uint64_t k = 0; k < a; ++k) {
            bytes.push_back(uint8_t(2 * symbol + 1));
            bytes.push_back(uint8_t(200 + symbol % 5));
        }
        const uint64_t next = a + b;
        a = b;
        b = next;
    }
    std::mt19937 random(3);
    std::shuffle(bytes.begin(), bytes.end(), random);
    bytes.resize(std::min<size_t>(bytes.size(), 3000000));
    expectRoundTrip(bytes, "Fibonacci frequencies");
}

TEST(DeflateRuns, CompressesRunsAndResidualsWell) {
    // 1000 rows of 100 zeros then 100 small residuals: the runs cost almost nothing and the
    // residuals about their entropy (a few bits each).
    std::mt19937 random(5);
    std::vector<uint8_t> bytes;
    for (int row = 0; row < 1000; ++row) {
        bytes.insert(bytes.end(), 100, 0);
        for (int i = 0; i < 100; ++i)
            bytes.push_back(uint8_t(random() % 4));
    }
    const std::vector<uint8_t> stream = encodeInPieces(bytes, {});
    EXPECT_LT(stream.size(), bytes.size() / 6) << "2 bits per residual and little for the runs";
    EXPECT_EQ(inflateRaw(stream, bytes.size()), bytes);
}

// Runs begin at every offset from where a block starts, after bytes in pairs (which start no
// run, and which the parse takes eight at a time): each quadruple of equal bytes is one literal
// and one run of three wherever it falls. 600 pairs and 200 quadruples of 256 byte values:
// 1400 literals of about 8 bits and 200 short runs, near 1580 bytes; the quadruples whose run
// starts at the last of eight bytes taken as four literals would make it about 1830.
TEST(DeflateRuns, FindsRunsAtEveryOffset) {
    for (int lead = 0; lead < 8; ++lead) {
        std::vector<uint8_t> bytes(size_t(lead), 7);
        uint8_t value = 1;
        auto next = [&] { return value = uint8_t(value * 5 + 3); };  // cycles through 256
        for (int quad = 0; quad < 200; ++quad) {
            for (int p = 0; p < 3; ++p)
                bytes.insert(bytes.end(), 2, next());
            bytes.insert(bytes.end(), 4, next());
        }
        const std::vector<uint8_t> stream = encodeInPieces(bytes, {});
        EXPECT_EQ(inflateRaw(stream, bytes.size()), bytes) << "lead " << lead;
        EXPECT_LT(stream.size(), 1650u) << "lead " << lead;
        expectRoundTrip(bytes, "cut", {size_t(lead) + 1, size_t(lead) + 9, 1000});
    }
}

}  // namespace
}  // namespace quaternia
