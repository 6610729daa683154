#include "quaternia/image/png_pieces.h"

#include <zlib.h>

#include <stdexcept>
#include <string>

#include "quaternia/image/deflate_runs.h"
#include "quaternia/image/png_lanes.h"
#include "quaternia/util/parallel.h"

namespace quaternia::png_pieces {

namespace {

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
uint32_t chunkCrc(const char (&type)[5], const uint8_t* data, size_t size) {
    const uLong crc = crc32_z(0, reinterpret_cast<const uint8_t*>(type), 4);
    // Not with a null pointer: zlib's crc32 then returns its initial value instead.
    return uint32_t(size > 0 ? crc32_z(crc, data, size) : crc);
}

// Length, type, data and the CRC of type and data (PNG spec 5.3), given or computed here.
void writeChunk(const PngSink& sink, const char (&type)[5], const uint8_t* data, size_t size,
                std::optional<uint32_t> crc = std::nullopt) {
    uint8_t head[8];
    putU32(head, uint32_t(size));
    std::copy(type, type + 4, head + 4);
    sink(head);
    if (size > 0) sink({data, size});
    uint8_t tail[4];
    putU32(tail, crc ? *crc : chunkCrc(type, data, size));
    sink(tail);
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
                 size_t piece, PieceScratch& scratch, EncodedPiece& encoded) {
    const size_t firstRow = pieces.firstRow(piece), endRow = pieces.endRow(piece, rows.height);
    const size_t filterFrom = pieces.filterFrom(piece);
    filterRows(rows, rowAt, filterFrom, endRow, scratch);
    const uint8_t* own = scratch.filtered.data() + (firstRow - filterFrom) * rows.filteredRowBytes;
    const size_t ownBytes = (endRow - firstRow) * rows.filteredRowBytes;
    encoded.adler = adler32Update(1, own, ownBytes);
    encoded.filteredBytes = ownBytes;

    const int before = own > scratch.filtered.data() ? own[-1] : -1;
    const bool last = piece + 1 == pieces.count;
    scratch.deflated.resize(std::max(scratch.deflated.size(), deflateRunsBound(ownBytes)));
    const size_t written = deflateRuns(own, ownBytes, before, last, scratch.deflated.data());
    std::vector<uint8_t>& out = encoded.compressed;
    out.clear();
    if (piece == 0) out.assign(kZlibHeader, kZlibHeader + sizeof kZlibHeader);
    out.insert(out.end(), scratch.deflated.begin(),
               scratch.deflated.begin() + std::ptrdiff_t(written));
    encoded.crc.reset();
    if (!last && out.size() <= kMaxChunkData)
        encoded.crc = chunkCrc("IDAT", out.data(), out.size());
}

}  // namespace

void checkFormat(const PngFormat& format) {
    if (format.width <= 0 || format.height <= 0)
        throw std::invalid_argument("cannot encode an empty image as PNG");
    if (format.bitDepth != 8 && format.bitDepth != 16)
        throw std::invalid_argument("PNG bit depth must be 8 or 16, got " +
                                    std::to_string(format.bitDepth));
}

void encodePieces(const RowLayout& rows, const PieceLayout& pieces, const PngRowSource& rowAt,
                  size_t begin, size_t end, int threads, std::vector<PieceScratch>& scratches,
                  std::span<EncodedPiece> out) {
    scratches.resize(std::max(scratches.size(), size_t(resolveThreadCount(threads))));
    ParallelOptions options;
    options.threads = threads;
    options.chunkSize = 1;  // one piece at a time, so uneven pieces balance
    parallelFor(int64_t(end - begin), options, [&](int64_t from, int64_t to, int thread) {
        PieceScratch& scratch = scratches[size_t(thread)];
        scratch.zeroRow.assign(rows.rowBytes, 0);
        scratch.rows[0].resize(rows.rowBytes);
        scratch.rows[1].resize(rows.rowBytes);
        for (size_t i = size_t(from); i < size_t(to); ++i)
            encodePiece(rows, pieces, rowAt, begin + i, scratch, out[i]);
    });
}

uint32_t combineAdler(uint32_t adler, const EncodedPiece& piece) {
    return uint32_t(adler32_combine(adler, piece.adler, z_off_t(piece.filteredBytes)));
}

void appendChecksum(EncodedPiece& last, uint32_t adler) {
    uint8_t checksum[4];
    putU32(checksum, adler);
    last.compressed.insert(last.compressed.end(), checksum, checksum + sizeof checksum);
}

void writeHeader(const PngFormat& format, const PngSink& sink) {
    sink(kPngSignature);
    uint8_t header[13];
    putU32(header, uint32_t(format.width));
    putU32(header + 4, uint32_t(format.height));
    header[8] = uint8_t(format.bitDepth);
    header[9] = uint8_t(format.colorType);
    header[10] = 0;  // compression: deflate
    header[11] = 0;  // filter method: the five adaptive filters
    header[12] = 0;  // not interlaced
    writeChunk(sink, "IHDR", header, sizeof header);
}

void writePiece(const EncodedPiece& piece, const PngSink& sink) {
    const std::vector<uint8_t>& bytes = piece.compressed;
    if (piece.crc) {
        writeChunk(sink, "IDAT", bytes.data(), bytes.size(), piece.crc);
        return;
    }
    for (size_t offset = 0; offset < bytes.size(); offset += kMaxChunkData)
        writeChunk(sink, "IDAT", bytes.data() + offset,
                   std::min(kMaxChunkData, bytes.size() - offset));
}

void writeEnd(const PngSink& sink) {
    writeChunk(sink, "IEND", nullptr, 0);
}

size_t pngFileBytes(std::span<const EncodedPiece> pieces) {
    size_t total = sizeof kPngSignature + 25 + 12;  // signature, IHDR, IEND
    for (const EncodedPiece& piece : pieces)
        total += piece.compressed.size() + 12 * (1 + piece.compressed.size() / kMaxChunkData);
    return total;
}

}  // namespace quaternia::png_pieces
