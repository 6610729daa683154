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

// The sizes of the image's rows: as the source gives them, and filtered (a filter byte first).
struct RowLayout {
    size_t height, rowBytes, filteredRowBytes, bytesPerPixel;

    explicit RowLayout(const PngFormat& format)
        : height(size_t(format.height)),
          rowBytes(pngRowBytes(format)),
          filteredRowBytes(rowBytes + 1),
          bytesPerPixel(size_t(pngChannels(format.colorType) * format.bitDepth / 8)) {}
};

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
    // Where a piece's filtering starts: one row before its own, whose last filtered byte a run
    // at its start may continue (Paeth predicts that row from the one above it, which the
    // source gives too). That row is filtered twice, by this piece and the one before, so that
    // nothing is shared between tasks.
    size_t filterFrom(size_t piece) const {
        const size_t first = firstRow(piece);
        return first - std::min<size_t>(first, 1);
    }
};

// Each thread's rows and buffers, kept from piece to piece (fresh ones for every piece were page
// faults: a piece's filtered rows and its deflate room are 256 KiB each).
struct PieceScratch {
    std::vector<uint8_t> zeroRow, rows[2], filtered, deflated;
};

// What the pieces' tasks give back, piece by piece.
struct EncodedPieces {
    // The zlib stream's checksum is of the filtered bytes, summed piece by piece (in lanes:
    // zlib's adler32 is scalar) and joined by adler32_combine.
    std::vector<uLong> adler;
    // Each piece deflated on its own, ending on a byte boundary (but the last, which ends with
    // the final block), so that the pieces simply join. The first carries the zlib header, the
    // last the checksum (appendChecksum, once every piece's sum is known).
    std::vector<std::vector<uint8_t>> compressed;
    // The CRC of each piece's IDAT chunk, taken by its task (but the last piece's, which the
    // checksum joins later, and pieces too large for one chunk).
    std::vector<std::optional<uLong>> crc;

    explicit EncodedPieces(size_t count) : adler(count), compressed(count), crc(count) {}
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

// Rows [from, end) filtered into scratch.filtered, each a scanline: the filter byte, then the
// row's bytes filtered.
void filterRows(const RowLayout& rows, const PngRowSource& rowAt, size_t from, size_t end,
                PieceScratch& scratch) {
    scratch.filtered.resize((end - from) * rows.filteredRowBytes);
    const uint8_t* previous =
        from == 0 ? scratch.zeroRow.data() : rowAt(from - 1, scratch.rows[0].data());
    int next = 1;  // the scratch row the source may write next; previous may be in the other
    for (size_t y = from; y < end; ++y) {
        const uint8_t* row = rowAt(y, scratch.rows[next].data());
        uint8_t* scanline = scratch.filtered.data() + (y - from) * rows.filteredRowBytes;
        scanline[0] = kPaethFilter;
        filterPaethRow(row, previous, rows.rowBytes, rows.bytesPerPixel, scanline + 1);
        previous = row;
        next ^= 1;
    }
}

// Piece `piece`: its rows filtered, their sum taken, deflated into the thread's room and kept at
// their size (after the zlib header in the first piece), and its chunk's CRC where it is known.
void encodePiece(const RowLayout& rows, const PieceLayout& pieces, const PngRowSource& rowAt,
                 size_t piece, PieceScratch& scratch, EncodedPieces& encoded) {
    const size_t firstRow = pieces.firstRow(piece), endRow = pieces.endRow(piece, rows.height);
    const size_t filterFrom = pieces.filterFrom(piece);
    filterRows(rows, rowAt, filterFrom, endRow, scratch);
    const uint8_t* own = scratch.filtered.data() + (firstRow - filterFrom) * rows.filteredRowBytes;
    const size_t ownBytes = (endRow - firstRow) * rows.filteredRowBytes;
    encoded.adler[piece] = adler32Update(1, own, ownBytes);

    const int before = own > scratch.filtered.data() ? own[-1] : -1;
    const bool last = piece + 1 == pieces.count;
    scratch.deflated.resize(std::max(scratch.deflated.size(), deflateRunsBound(ownBytes)));
    const size_t written = deflateRuns(own, ownBytes, before, last, scratch.deflated.data());
    std::vector<uint8_t>& out = encoded.compressed[piece];
    if (piece == 0) out.assign(kZlibHeader, kZlibHeader + sizeof kZlibHeader);
    out.insert(out.end(), scratch.deflated.begin(),
               scratch.deflated.begin() + std::ptrdiff_t(written));
    if (!last && out.size() <= kMaxChunkData)
        encoded.crc[piece] = chunkCrc("IDAT", out.data(), out.size());
}

// The zlib stream's checksum, the pieces' sums joined, at the end of the last piece.
void appendChecksum(const RowLayout& rows, const PieceLayout& pieces, EncodedPieces& encoded) {
    uLong adler = adler32_z(0, nullptr, 0);
    for (size_t piece = 0; piece < pieces.count; ++piece) {
        const size_t pieceRows = pieces.endRow(piece, rows.height) - pieces.firstRow(piece);
        adler = adler32_combine(adler, encoded.adler[piece],
                                z_off_t(pieceRows * rows.filteredRowBytes));
    }
    uint8_t checksum[4];
    putU32(checksum, uint32_t(adler));
    std::vector<uint8_t>& last = encoded.compressed.back();
    last.insert(last.end(), checksum, checksum + sizeof checksum);
}

// The PNG file: signature, IHDR, the pieces as IDAT chunks (each in several where it is too
// large for one), IEND.
std::vector<uint8_t> assemblePng(const PngFormat& format, const EncodedPieces& encoded) {
    size_t total = sizeof kPngSignature + 25 + 12;  // signature, IHDR, IEND
    for (const std::vector<uint8_t>& piece : encoded.compressed)
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
    for (size_t p = 0; p < encoded.compressed.size(); ++p) {
        const std::vector<uint8_t>& piece = encoded.compressed[p];
        if (encoded.crc[p]) {
            appendChunk(png, "IDAT", piece.data(), piece.size(), encoded.crc[p]);
            continue;
        }
        for (size_t offset = 0; offset < piece.size(); offset += kMaxChunkData)
            appendChunk(png, "IDAT", piece.data() + offset,
                        std::min(kMaxChunkData, piece.size() - offset));
    }
    appendChunk(png, "IEND", nullptr, 0);
    return png;
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
    const RowLayout rows(format);
    const PieceLayout pieces(rows.height, rows.filteredRowBytes);
    // Each piece is filtered and deflated by one task, from the rows the source gives it: the
    // samples never exist as a whole image.
    EncodedPieces encoded(pieces.count);
    std::vector<PieceScratch> scratches(size_t(resolveThreadCount(threads)));
    ParallelOptions options;
    options.threads = threads;
    options.chunkSize = 1;  // one piece at a time, so uneven pieces balance
    parallelFor(int64_t(pieces.count), options, [&](int64_t begin, int64_t end, int thread) {
        PieceScratch& scratch = scratches[size_t(thread)];
        scratch.zeroRow.assign(rows.rowBytes, 0);
        scratch.rows[0].resize(rows.rowBytes);
        scratch.rows[1].resize(rows.rowBytes);
        for (size_t piece = size_t(begin); piece < size_t(end); ++piece)
            encodePiece(rows, pieces, rowAt, piece, scratch, encoded);
    });
    appendChecksum(rows, pieces, encoded);
    return assemblePng(format, encoded);
}

}  // namespace quaternia
