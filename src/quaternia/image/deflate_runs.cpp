#include "quaternia/image/deflate_runs.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <vector>

namespace quaternia {

namespace {

// RFC 1951 3.2.5: the length codes 257..285, their first lengths and extra bits.
constexpr int kLengthCodes = 29;
constexpr std::array<uint16_t, kLengthCodes> kLengthBase = {
    3,  4,  5,  6,  7,  8,  9,  10, 11,  13,  15,  17,  19,  23, 27,
    31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
constexpr std::array<uint8_t, kLengthCodes> kLengthExtraBits = {
    0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
constexpr int kMinRun = 3, kMaxRun = 258;
constexpr int kEndOfBlock = 256;
constexpr int kLiteralLengthSymbols = 257 + kLengthCodes;  // 286
constexpr int kCodeLengthSymbols = 19;
// RFC 1951 3.2.7: the order in which the code length code's lengths are sent.
constexpr std::array<uint8_t, kCodeLengthSymbols> kCodeLengthOrder = {
    16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15};
constexpr int kMaxCodeLength = 15, kMaxCodeLengthCodeLength = 7;
// Input bytes per block: small enough that each block's codes follow the statistics of its
// rows, and that a block stored instead fits one stored block (at most 65535 bytes).
constexpr size_t kBlockBytes = 65535;

// Lengths 3..258 to their length code (0..28 for symbols 257..285).
constexpr std::array<uint8_t, kMaxRun + 1> makeLengthCodes() {
    std::array<uint8_t, kMaxRun + 1> codes{};
    for (int code = 0; code < kLengthCodes; ++code) {
        const int end = code + 1 < kLengthCodes ? kLengthBase[size_t(code + 1)] : kMaxRun + 1;
        for (int length = kLengthBase[size_t(code)]; length < end; ++length)
            codes[size_t(length)] = uint8_t(code);
    }
    codes[kMaxRun] = kLengthCodes - 1;  // 258 has a code of its own (285), not 284 + 31
    return codes;
}
constexpr std::array<uint8_t, kMaxRun + 1> kLengthCodeOf = makeLengthCodes();

// Bits go out least significant first (RFC 1951 3.1.1), through a 64-bit accumulator that
// keeps fewer than 8 bits between puts: each put stores all 8 bytes of it and moves on by the
// whole bytes filled, without a branch (the output needs 8 bytes of room past its end, which
// deflateRunsBound leaves).
class BitWriter {
  public:
    explicit BitWriter(uint8_t* out) : out_(out), start_(out) {}
    // `count` <= 56 bits of `bits`, the first to go out in the lowest bit.
    void put(uint64_t bits, int count) {
        buffer_ |= bits << filled_;
        filled_ += count;
        std::memcpy(out_, &buffer_, 8);  // little-endian: the lowest bits first
        const int bytes = filled_ >> 3;  // at most 7: filled_ < 8 + 56
        out_ += bytes;
        buffer_ >>= 8 * bytes;
        filled_ &= 7;
    }
    // To the next byte boundary with zero bits.
    void alignToByte() {
        if (filled_ > 0) *out_++ = uint8_t(buffer_);
        buffer_ = 0;
        filled_ = 0;
    }
    void putBytes(const uint8_t* bytes, size_t count) {  // after alignToByte
        std::memcpy(out_, bytes, count);
        out_ += count;
    }
    size_t written() const { return size_t(out_ - start_); }

  private:
    uint8_t* out_;
    uint8_t* start_;
    uint64_t buffer_ = 0;
    int filled_ = 0;
};

// Code lengths of at most maxLength bits for the given frequencies (0 for unused symbols), by
// Huffman's construction; where the tree is deeper than allowed, the frequencies are halved
// (rounding up, so that used symbols stay used) and the tree built again: flatter
// distributions give shallower trees, and equal frequencies a balanced one.
void huffmanLengths(const uint32_t* frequency, int symbols, int maxLength, uint8_t* lengths) {
    constexpr int kMaxSymbols = kLiteralLengthSymbols;
    uint32_t weight[kMaxSymbols];
    std::copy(frequency, frequency + symbols, weight);
    for (;;) {
        // Leaves sorted by weight, ties by symbol (weight and symbol in one key), then the
        // two-queue construction of Huffman's tree.
        uint64_t leaves[kMaxSymbols];
        size_t n = 0;
        for (int s = 0; s < symbols; ++s) {
            lengths[s] = 0;
            if (weight[s] > 0) leaves[n++] = uint64_t(weight[s]) << 16 | uint64_t(s);
        }
        if (n == 0) return;
        if (n == 1) {
            lengths[leaves[0] & 0xffff] = 1;
            return;
        }
        std::sort(leaves, leaves + n);
        uint64_t nodeWeight[2 * kMaxSymbols];
        int parent[2 * kMaxSymbols];
        for (size_t i = 0; i < n; ++i)
            nodeWeight[i] = leaves[i] >> 16, parent[i] = -1;
        size_t nextLeaf = 0, nextInner = n, made = n;
        auto takeSmallest = [&]() {
            if (nextLeaf < n &&
                (nextInner >= made || nodeWeight[nextLeaf] <= nodeWeight[nextInner]))
                return nextLeaf++;
            return nextInner++;
        };
        while (made < 2 * n - 1) {
            const size_t a = takeSmallest(), b = takeSmallest();
            nodeWeight[made] = nodeWeight[a] + nodeWeight[b];
            parent[made] = -1;
            parent[a] = parent[b] = int(made);
            ++made;
        }
        // Depths from the root down: a parent always comes after its children.
        int depth[2 * kMaxSymbols];
        int deepest = 0;
        for (size_t i = 2 * n - 1; i-- > 0;) {
            depth[i] = parent[i] >= 0 ? depth[parent[i]] + 1 : 0;
            if (i < n) deepest = std::max(deepest, depth[i]);
        }
        if (deepest <= maxLength) {
            for (size_t i = 0; i < n; ++i)
                lengths[leaves[i] & 0xffff] = uint8_t(depth[i]);
            return;
        }
        for (int s = 0; s < symbols; ++s)
            weight[s] = (weight[s] + 1) / 2;
    }
}

// Canonical codes from code lengths (RFC 1951 3.2.2), bit-reversed to go out first bit first.
void canonicalCodes(const uint8_t* lengths, int symbols, uint16_t* codes) {
    int count[kMaxCodeLength + 1] = {};
    for (int s = 0; s < symbols; ++s)
        ++count[lengths[s]];
    count[0] = 0;
    int next[kMaxCodeLength + 2] = {};
    int code = 0;
    for (int bits = 1; bits <= kMaxCodeLength; ++bits) {
        code = (code + count[bits - 1]) << 1;
        next[bits] = code;
    }
    for (int s = 0; s < symbols; ++s) {
        const int length = lengths[s];
        if (length == 0) continue;
        int value = next[length]++, reversed = 0;
        for (int b = 0; b < length; ++b, value >>= 1)
            reversed = (reversed << 1) | (value & 1);
        codes[s] = uint16_t(reversed);
    }
}

// A block's parse: each symbol is a literal byte (< 256) or a run, 256 + its length.
struct Parse {
    std::vector<uint16_t> symbols;  // `count` of them
    size_t count = 0;
    uint32_t literalLengthFrequency[kLiteralLengthSymbols] = {};
    bool anyRun = false;
};

// How long the run of `previous` starting at input[i] is, up to kMaxRun and the end.
inline size_t runLength(const uint8_t* input, size_t i, size_t end, uint8_t previous) {
    const size_t limit = std::min(end, i + kMaxRun);
    uint64_t pattern = 0x0101010101010101ull * previous;
    size_t j = i;
    while (j + 8 <= limit) {
        uint64_t word;
        std::memcpy(&word, input + j, 8);
        const uint64_t differ = word ^ pattern;
        if (differ != 0) return j - i + size_t(__builtin_ctzll(differ) / 8);
        j += 8;
    }
    while (j < limit && input[j] == previous)
        ++j;
    return j - i;
}

// 0x80 in each byte of the little-endian `word` that equals the byte before it (`first`'s
// for its lowest), 0 elsewhere: exact in every byte (no borrow crosses between bytes).
inline uint64_t equalToBefore(uint64_t word, uint8_t first) {
    constexpr uint64_t kLow7 = 0x7f7f7f7f7f7f7f7full;
    const uint64_t differ = word ^ (word << 8 | first);
    return ~(((differ & kLow7) + kLow7) | differ | kLow7);
}

// `previous` is the byte before input[begin], or -1 where there is none.
void parseBlock(const uint8_t* input, size_t begin, size_t end, int previous, Parse& parse) {
    parse.symbols.resize(end - begin);
    uint16_t* out = parse.symbols.data();
    // Two tables of counts, for even and odd bytes of the literal runs below, so that equal
    // neighbours do not wait on each other's increment; summed at the end.
    uint32_t counts[2][kLiteralLengthSymbols] = {};
    bool anyRun = false;
    for (size_t i = begin; i < end;) {
        // A run starts where a byte and the two after it all equal the byte before it: where
        // none of the next eight bytes does, they are eight literals (most of a rendered
        // image's bytes, whose equal neighbours come in pairs more often than in runs).
        if (previous >= 0 && i + 10 <= end) {
            uint64_t word, later;
            std::memcpy(&word, input + i, 8);
            std::memcpy(&later, input + i + 2, 8);
            // Flags (0x80 in a byte) of the bytes i + k equal to the byte before them, k < 8,
            // and of the bytes i + 2 + k equal to theirs.
            const uint64_t equal = equalToBefore(word, uint8_t(previous));
            const uint64_t equalLater = equalToBefore(later, input[i + 1]);
            const uint64_t next = equal >> 8 | (equalLater << 8 & 0xff00000000000000ull);
            if ((equal & next & equalLater) == 0) {
                for (int k = 0; k < 8; ++k) {
                    const uint8_t byte = uint8_t(word >> (8 * k));
                    out[k] = byte;
                    ++counts[k & 1][byte];
                }
                out += 8;
                i += 8;
                previous = int(word >> 56);
                continue;
            }
        }
        const uint8_t byte = input[i];
        if (byte == previous) {
            const size_t run = runLength(input, i, end, byte);
            if (run >= kMinRun) {
                *out++ = uint16_t(256 + run);
                ++counts[0][257 + kLengthCodeOf[run]];
                anyRun = true;
                i += run;
                continue;
            }
        }
        *out++ = byte;
        ++counts[0][byte];
        previous = byte;
        ++i;
    }
    uint32_t* frequency = parse.literalLengthFrequency;
    for (int symbol = 0; symbol < kLiteralLengthSymbols; ++symbol)
        frequency[symbol] = counts[0][symbol] + counts[1][symbol];
    ++frequency[kEndOfBlock];
    parse.count = size_t(out - parse.symbols.data());
    parse.anyRun = anyRun;
}

// A symbol of the code length code (RFC 1951 3.2.7): a length 0..15, or a run of zeros (17:
// 3..10 of them, 18: 11..138) with its count less the shortest in `extra`.
struct CodeLengthSymbol {
    uint8_t symbol, extra;
};

// A block's codes as its header sends them (RFC 1951 3.2.7): the literal/length code's lengths,
// the distance code's one length, and the code length code those lengths are sent in.
struct BlockCodes {
    uint8_t literalLengths[kLiteralLengthSymbols];
    int literalCount = kLiteralLengthSymbols;  // HLIT + 257: the lengths sent, trailing zeros cut
    // Runs are at distance 1, distance code 0: one code of one bit (RFC 1951 3.2.7 allows a
    // single distance code), or none at all (one distance code of zero bits) without runs.
    uint8_t distanceLength = 0;
    std::vector<CodeLengthSymbol> lengthSymbols;  // the lengths of both codes, zeros in runs
    uint8_t codeLengthLengths[kCodeLengthSymbols];
    int codeLengthCount = kCodeLengthSymbols;  // HCLEN + 4, in kCodeLengthOrder
};

// The literal/length code of the parse (and the distance code's length).
void buildLiteralCode(const Parse& parse, BlockCodes& codes) {
    uint32_t frequency[kLiteralLengthSymbols];
    std::copy(std::begin(parse.literalLengthFrequency), std::end(parse.literalLengthFrequency),
              frequency);
    // A code of one symbol would be incomplete, which decoders refuse for literals and lengths:
    // a block of only its end gets a second, unused symbol.
    if (std::count_if(frequency, frequency + kLiteralLengthSymbols,
                      [](uint32_t f) { return f > 0; }) < 2)
        frequency[0] = 1;
    huffmanLengths(frequency, kLiteralLengthSymbols, kMaxCodeLength, codes.literalLengths);
    codes.literalCount = kLiteralLengthSymbols;
    while (codes.literalCount > 257 && codes.literalLengths[codes.literalCount - 1] == 0)
        --codes.literalCount;
    codes.distanceLength = parse.anyRun ? 1 : 0;
}

// The code lengths of both codes in one sequence, zeros in runs (symbols 17 and 18), and the
// code length code that sends them.
void buildCodeLengthCode(BlockCodes& codes) {
    std::vector<uint8_t> sequence(codes.literalLengths, codes.literalLengths + codes.literalCount);
    sequence.push_back(codes.distanceLength);
    std::vector<CodeLengthSymbol>& lengthSymbols = codes.lengthSymbols;
    uint32_t codeLengthFrequency[kCodeLengthSymbols] = {};
    for (size_t i = 0; i < sequence.size();) {
        size_t zeros = 0;
        while (i + zeros < sequence.size() && sequence[i + zeros] == 0 && zeros < 138)
            ++zeros;
        if (zeros >= 11) {
            lengthSymbols.push_back({18, uint8_t(zeros - 11)});
            i += zeros;
        } else if (zeros >= 3) {
            lengthSymbols.push_back({17, uint8_t(zeros - 3)});
            i += zeros;
        } else {
            lengthSymbols.push_back({sequence[i], 0});
            ++i;
        }
        ++codeLengthFrequency[lengthSymbols.back().symbol];
    }
    // Decoders refuse an incomplete code length code: with one symbol in use, a second one.
    if (std::count_if(std::begin(codeLengthFrequency), std::end(codeLengthFrequency),
                      [](uint32_t f) { return f > 0; }) < 2)
        ++codeLengthFrequency[codeLengthFrequency[0] > 0 ? 18 : 0];
    huffmanLengths(codeLengthFrequency, kCodeLengthSymbols, kMaxCodeLengthCodeLength,
                   codes.codeLengthLengths);
    codes.codeLengthCount = kCodeLengthSymbols;
    while (codes.codeLengthCount > 4 &&
           codes.codeLengthLengths[kCodeLengthOrder[size_t(codes.codeLengthCount - 1)]] == 0)
        --codes.codeLengthCount;
}

// The size of the block with these codes, header included, in bits.
uint64_t dynamicBlockBits(const Parse& parse, const BlockCodes& codes) {
    uint64_t bits = 3 + 5 + 5 + 4 + 3 * uint64_t(codes.codeLengthCount);
    for (const CodeLengthSymbol& s : codes.lengthSymbols)
        bits += codes.codeLengthLengths[s.symbol] + (s.symbol == 18 ? 7 : s.symbol == 17 ? 3 : 0);
    for (int s = 0; s < kLiteralLengthSymbols; ++s) {
        uint64_t perSymbol = codes.literalLengths[s];
        if (s > 256) perSymbol += kLengthExtraBits[size_t(s - 257)] + codes.distanceLength;
        bits += uint64_t(parse.literalLengthFrequency[s]) * perSymbol;
    }
    return bits;
}

// The size of `bytes` bytes as a stored block, in bits (at most 7 of them to the byte boundary).
uint64_t storedBlockBits(size_t bytes) {
    return 3 + 7 + 32 + 8 * uint64_t(bytes);
}

void writeStoredBlock(const uint8_t* bytes, size_t count, bool final, BitWriter& out) {
    out.put(final ? 1 : 0, 3);  // BFINAL, BTYPE 00
    out.alignToByte();
    const uint32_t length = uint32_t(count);
    out.put(length | (uint32_t(~length & 0xffff) << 16), 32);
    out.putBytes(bytes, count);
}

// A dynamic block's header: its type, the code counts, the code length code, and the lengths
// of both codes in that code.
void writeDynamicHeader(const BlockCodes& codes, bool final, BitWriter& out) {
    uint16_t codeLengthCodes[kCodeLengthSymbols] = {};
    canonicalCodes(codes.codeLengthLengths, kCodeLengthSymbols, codeLengthCodes);
    out.put((final ? 1 : 0) | (2 << 1), 3);  // BFINAL, BTYPE 10: dynamic codes
    out.put(uint64_t(codes.literalCount - 257), 5);
    out.put(0, 5);  // one distance code
    out.put(uint64_t(codes.codeLengthCount - 4), 4);
    for (int i = 0; i < codes.codeLengthCount; ++i)
        out.put(codes.codeLengthLengths[kCodeLengthOrder[size_t(i)]], 3);
    for (const CodeLengthSymbol& s : codes.lengthSymbols) {
        out.put(codeLengthCodes[s.symbol], codes.codeLengthLengths[s.symbol]);
        if (s.symbol == 17) out.put(s.extra, 3);
        if (s.symbol == 18) out.put(s.extra, 7);
    }
}

// Each run as one put: its length code, extra bits and the distance code's one 0 bit.
struct RunCode {
    uint32_t bits;
    uint8_t count;
};
using RunCodes = std::array<RunCode, kMaxRun + 1>;

void makeRunCodes(const BlockCodes& codes, const uint16_t* literalCodes, RunCodes& runCodes) {
    for (int length = kMinRun; length <= kMaxRun; ++length) {
        const int code = kLengthCodeOf[size_t(length)];
        const int symbol = 257 + code;
        const int extraBits = kLengthExtraBits[size_t(code)];
        const uint32_t extra = uint32_t(length - kLengthBase[size_t(code)]);
        runCodes[size_t(length)] = {
            uint32_t(literalCodes[symbol]) | (extra << codes.literalLengths[symbol]),
            uint8_t(codes.literalLengths[symbol] + extraBits + codes.distanceLength)};
    }
}

// The parse's symbols in the block's codes, and the end of the block.
void writeSymbols(const Parse& parse, const BlockCodes& codes, const uint16_t* literalCodes,
                  BitWriter& out) {
    RunCodes runCodes{};
    if (parse.anyRun) makeRunCodes(codes, literalCodes, runCodes);
    // A literal's code and length in one word.
    uint32_t literalWords[256];
    for (int s = 0; s < 256; ++s)
        literalWords[s] = uint32_t(literalCodes[s]) | uint32_t(codes.literalLengths[s]) << 16;
    const uint16_t* symbols = parse.symbols.data();
    for (size_t k = 0; k < parse.count; ++k) {
        // Three literals in one put where they come together (at most 45 bits).
        if (k + 3 <= parse.count && (symbols[k] | symbols[k + 1] | symbols[k + 2]) < 256) {
            const uint32_t a = literalWords[symbols[k]], b = literalWords[symbols[k + 1]],
                           c = literalWords[symbols[k + 2]];
            const int aBits = int(a >> 16), bBits = int(b >> 16);
            out.put(uint64_t(a & 0xffff) | uint64_t(b & 0xffff) << aBits |
                        uint64_t(c & 0xffff) << (aBits + bBits),
                    aBits + bBits + int(c >> 16));
            k += 2;
            continue;
        }
        const uint16_t symbol = symbols[k];
        if (symbol < 256) {
            const uint32_t word = literalWords[symbol];
            out.put(word & 0xffff, int(word >> 16));
        } else {
            const RunCode& run = runCodes[size_t(symbol - 256)];
            out.put(run.bits, run.count);  // the distance code 0 is the bit 0 above them
        }
    }
    out.put(literalCodes[kEndOfBlock], codes.literalLengths[kEndOfBlock]);
}

// Writes one block: with its own Huffman codes, or stored where that is shorter.
void writeBlock(const uint8_t* input, size_t begin, size_t end, const Parse& parse, bool final,
                BitWriter& out) {
    BlockCodes codes;
    buildLiteralCode(parse, codes);
    buildCodeLengthCode(codes);
    if (storedBlockBits(end - begin) <= dynamicBlockBits(parse, codes)) {
        writeStoredBlock(input + begin, end - begin, final, out);
        return;
    }
    uint16_t literalCodes[kLiteralLengthSymbols] = {};
    canonicalCodes(codes.literalLengths, kLiteralLengthSymbols, literalCodes);
    writeDynamicHeader(codes, final, out);
    writeSymbols(parse, codes, literalCodes, out);
}

}  // namespace

size_t deflateRunsBound(size_t size) {
    const size_t blocks = std::max<size_t>(1, (size + kBlockBytes - 1) / kBlockBytes);
    return size + 5 * blocks + 5 + 16;
}

size_t deflateRuns(const uint8_t* input, size_t size, int before, bool last, uint8_t* out) {
    BitWriter writer(out);
    Parse parse;
    for (size_t begin = 0; begin < size; begin += kBlockBytes) {
        const size_t end = std::min(size, begin + kBlockBytes);
        parseBlock(input, begin, end, begin == 0 ? before : input[begin - 1], parse);
        writeBlock(input, begin, end, parse, last && end == size, writer);
    }
    if (size == 0 || !last) {
        // An empty stored block: the final one, or one that leaves the stream on a byte
        // boundary for the next piece.
        writer.put(last ? 1 : 0, 3);
        writer.alignToByte();
        writer.put(0xffff0000u, 32);
    }
    writer.alignToByte();
    return writer.written();
}

}  // namespace quaternia
