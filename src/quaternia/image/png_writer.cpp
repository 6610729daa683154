#include "quaternia/image/png_writer.h"

#include <zlib.h>

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>

#include "quaternia/image/deflate_runs.h"
#include "quaternia/image/png_lanes.h"
#include "quaternia/util/parallel.h"

namespace quaternia {

namespace {

// About this many filtered bytes per piece: big enough that the pieces' seams (an empty stored
// block, and new Huffman codes) cost little, small enough that a 1080p frame gives every core
// several pieces. The cut depends on the image alone.
constexpr size_t kPieceBytes = size_t(256) << 10;
// The Paeth filter, and deflate with runs of the byte before as its only matches
// (deflate_runs.h: what zlib's level 1 with Z_RLE does, several times faster): as libpng was
// set up before, speed over the last few percent of size. On renders the runs made 1080p
// frames about 13% smaller than zlib's default strategy at level 1 (BM_EncodePng).
// The zlib header for a 32 KiB window and the fastest level (RFC 1950: CMF 0x78, FLG 0x01,
// whose check bits make 0x7801 a multiple of 31).
constexpr uint8_t kZlibHeader[2] = {0x78, 0x01};
// PNG's limit on a chunk's length is 2^31 - 1; a piece larger than this (only with rows of
// hundreds of MiB) spreads over several IDAT chunks.
constexpr size_t kMaxChunkData = size_t(1) << 30;

constexpr uint8_t kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
constexpr uint8_t kPaethFilter = 4;

void putU32(uint8_t* out, uint32_t value) {
    out[0] = uint8_t(value >> 24);
    out[1] = uint8_t(value >> 16);
    out[2] = uint8_t(value >> 8);
    out[3] = uint8_t(value);
}

// The CRC of a chunk's type and data (PNG spec 5.3).
uLong chunkCrc(const char (&type)[5], const uint8_t* data, size_t size) {
    const uLong crc = crc32_z(0, reinterpret_cast<const uint8_t*>(type), 4);
    // Not with a null pointer: zlib's crc32 then returns its initial value instead.
    return size > 0 ? crc32_z(crc, data, size) : crc;
}

// Length, type, data and the CRC of type and data (PNG spec 5.3), given or computed here.
void appendChunk(std::vector<uint8_t>& png, const char (&type)[5], const uint8_t* data, size_t size,
                 std::optional<uLong> crc = std::nullopt) {
    uint8_t field[4];
    putU32(field, uint32_t(size));
    png.insert(png.end(), field, field + 4);
    const auto* typeBytes = reinterpret_cast<const uint8_t*>(type);
    png.insert(png.end(), typeBytes, typeBytes + 4);
    if (size > 0) png.insert(png.end(), data, data + size);
    putU32(field, uint32_t(crc ? *crc : chunkCrc(type, data, size)));
    png.insert(png.end(), field, field + 4);
}

// Rows [firstRow, endRow) of each piece; every piece but the last has rowsPerPiece rows.
struct PieceLayout {
    size_t rowsPerPiece = 1, count = 0;

    PieceLayout(size_t height, size_t filteredRowBytes)
        : rowsPerPiece(std::max<size_t>(1, kPieceBytes / filteredRowBytes)),
          count((height + rowsPerPiece - 1) / rowsPerPiece) {}
    size_t firstRow(size_t piece) const { return piece * rowsPerPiece; }
    size_t endRow(size_t piece, size_t height) const {
        return std::min(height, (piece + 1) * rowsPerPiece);
    }
};

void checkFormat(const PngFormat& format) {
    if (format.width <= 0 || format.height <= 0)
        throw std::invalid_argument("cannot encode an empty image as PNG");
    if (format.bitDepth != 8 && format.bitDepth != 16)
        throw std::invalid_argument("PNG bit depth must be 8 or 16, got " +
                                    std::to_string(format.bitDepth));
}
void checkFormat(const PngFormat& format, size_t sampleBytes) {
    checkFormat(format);
    if (sampleBytes != pngRowBytes(format) * size_t(format.height))
        throw std::invalid_argument("PNG samples do not match the image's size");
}

}  // namespace

size_t pngRowBytes(const PngFormat& format) {
    return size_t(format.width) * size_t(pngChannels(format.colorType)) *
           size_t(format.bitDepth / 8);
}

std::vector<uint8_t> writePngBytes(const PngFormat& format, std::span<const uint8_t> samples,
                                   int threads) {
    checkFormat(format, samples.size());
    const size_t rowBytes = pngRowBytes(format);
    return writePngRows(
        format, [&](size_t y, uint8_t*) { return samples.data() + y * rowBytes; }, threads);
}

std::vector<uint8_t> writePngRows(const PngFormat& format, const PngRowSource& rowAt, int threads) {
    checkFormat(format);
    const size_t height = size_t(format.height);
    const size_t rowBytes = pngRowBytes(format);
    const size_t filteredRowBytes = rowBytes + 1;
    const size_t bytesPerPixel = size_t(pngChannels(format.colorType) * format.bitDepth / 8);
    const PieceLayout pieces(height, filteredRowBytes);
    // Each piece is filtered and deflated by one task, from the rows the source gives it: its
    // own, and before them the row whose last filtered byte a run at its start may continue and
    // the one row above that, which Paeth predicts from. That row is filtered twice, by this
    // piece and the one before; nothing is shared between tasks, and the samples never exist as
    // a whole image.
    const size_t rowsBefore = 1;

    ParallelOptions options;
    options.threads = threads;
    options.chunkSize = 1;  // one piece at a time, so uneven pieces balance

    // The zlib stream's checksum is of the filtered bytes, summed piece by piece (in lanes:
    // zlib's adler32 is scalar) and joined by adler32_combine.
    std::vector<uLong> pieceAdler(pieces.count);
    // Each piece deflated on its own, ending on a byte boundary (but the last, which ends with
    // the final block), so that the pieces simply join. The first carries the zlib header, the
    // last the checksum (appended below, once every piece's sum is known).
    std::vector<std::vector<uint8_t>> compressed(pieces.count);
    // The CRC of each piece's IDAT chunk, taken by its task (but the last piece's, which the
    // checksum joins later, and pieces too large for one chunk).
    std::vector<std::optional<uLong>> pieceCrc(pieces.count);
    // Each thread's rows and buffers, kept from piece to piece (fresh ones for every piece
    // were page faults: a piece's filtered rows and its deflate room are 256 KiB each).
    struct Scratch {
        std::vector<uint8_t> zeroRow, rows[2], filtered, deflated;
    };
    std::vector<Scratch> scratches(size_t(resolveThreadCount(threads)));
    parallelFor(int64_t(pieces.count), options, [&](int64_t begin, int64_t end, int thread) {
        Scratch& scratch = scratches[size_t(thread)];
        scratch.zeroRow.assign(rowBytes, 0);
        scratch.rows[0].resize(rowBytes);
        scratch.rows[1].resize(rowBytes);
        std::vector<uint8_t>& filtered = scratch.filtered;
        for (size_t piece = size_t(begin); piece < size_t(end); ++piece) {
            const size_t firstRow = pieces.firstRow(piece), endRow = pieces.endRow(piece, height);
            const size_t filterFrom = firstRow - std::min(firstRow, rowsBefore);
            filtered.resize((endRow - filterFrom) * filteredRowBytes);
            const uint8_t* previous = filterFrom == 0
                                          ? scratch.zeroRow.data()
                                          : rowAt(filterFrom - 1, scratch.rows[0].data());
            int next =
                1;  // the scratch row the source may write next; previous may be in the other
            for (size_t y = filterFrom; y < endRow; ++y) {
                const uint8_t* row = rowAt(y, scratch.rows[next].data());
                // A scanline: the filter byte, then the row's bytes filtered.
                uint8_t* scanline = filtered.data() + (y - filterFrom) * filteredRowBytes;
                scanline[0] = kPaethFilter;
                filterPaethRow(row, previous, rowBytes, bytesPerPixel, scanline + 1);
                previous = row;
                next ^= 1;
            }
            const uint8_t* own = filtered.data() + (firstRow - filterFrom) * filteredRowBytes;
            const size_t ownBytes = (endRow - firstRow) * filteredRowBytes;
            pieceAdler[piece] = adler32Update(1, own, ownBytes);

            // Deflated into the thread's room, then kept at its size.
            const int before = own > filtered.data() ? own[-1] : -1;
            scratch.deflated.resize(std::max(scratch.deflated.size(), deflateRunsBound(ownBytes)));
            const size_t written = deflateRuns(own, ownBytes, before, piece + 1 == pieces.count,
                                               scratch.deflated.data());
            std::vector<uint8_t>& out = compressed[piece];
            if (piece == 0) out.assign(kZlibHeader, kZlibHeader + sizeof kZlibHeader);
            out.insert(out.end(), scratch.deflated.begin(),
                       scratch.deflated.begin() + std::ptrdiff_t(written));
            if (piece + 1 < pieces.count && out.size() <= kMaxChunkData)
                pieceCrc[piece] = chunkCrc("IDAT", out.data(), out.size());
        }
    });
    uLong adler = adler32_z(0, nullptr, 0);
    for (size_t piece = 0; piece < pieces.count; ++piece) {
        const size_t rows = pieces.endRow(piece, height) - pieces.firstRow(piece);
        adler = adler32_combine(adler, pieceAdler[piece], z_off_t(rows * filteredRowBytes));
    }
    uint8_t checksum[4];
    putU32(checksum, uint32_t(adler));
    compressed.back().insert(compressed.back().end(), checksum, checksum + sizeof checksum);

    size_t total = sizeof kPngSignature + 25 + 12;  // signature, IHDR, IEND
    for (const std::vector<uint8_t>& piece : compressed)
        total += piece.size() + 12 * (1 + piece.size() / kMaxChunkData);
    std::vector<uint8_t> png;
    png.reserve(total);
    png.assign(kPngSignature, kPngSignature + sizeof kPngSignature);
    uint8_t header[13];
    putU32(header, uint32_t(format.width));
    putU32(header + 4, uint32_t(format.height));
    header[8] = uint8_t(format.bitDepth);
    header[9] = uint8_t(format.colorType);
    header[10] = 0;  // compression: deflate
    header[11] = 0;  // filter method: the five adaptive filters
    header[12] = 0;  // not interlaced
    appendChunk(png, "IHDR", header, sizeof header);
    for (size_t p = 0; p < pieces.count; ++p) {
        const std::vector<uint8_t>& piece = compressed[p];
        if (pieceCrc[p]) {
            appendChunk(png, "IDAT", piece.data(), piece.size(), pieceCrc[p]);
            continue;
        }
        for (size_t offset = 0; offset < piece.size(); offset += kMaxChunkData)
            appendChunk(png, "IDAT", piece.data() + offset,
                        std::min(kMaxChunkData, piece.size() - offset));
    }
    appendChunk(png, "IEND", nullptr, 0);
    return png;
}

}  // namespace quaternia
