// The pieces of our PNG writer, shared by writePngRows (png_writer.h), which encodes a whole
// image at once, and PngStreamWriter (png_stream_writer.h), which encodes it as its rows arrive:
// one implementation of the cut, the filtering, the deflating and the chunks, so that both
// write the same bytes for the same rows. Internal to the image layer.
//
// The rows are cut into fixed pieces that are filtered and deflated on their own (as pigz
// does), and the pieces, joined, form one ordinary zlib stream that any decoder reads. The cut
// depends on the image's layout alone, so the bytes never depend on the number of threads.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "quaternia/image/png_writer.h"

namespace quaternia::png_pieces {

// About this many filtered bytes per piece: big enough that the pieces' seams (an empty stored
// block, and new Huffman codes) cost little, small enough that a 1080p frame gives every core
// several pieces.
constexpr size_t kPieceBytes = size_t(256) << 10;

// Throws std::invalid_argument for an empty image or a bit depth other than 8 or 16.
void checkFormat(const PngFormat& format);

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
    // source gives too, so a piece reads the two rows before its own). That row is filtered
    // twice, by this piece and the one before, so that nothing is shared between tasks.
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

// One piece, filtered and deflated.
struct EncodedPiece {
    // The Adler-32 of the piece's filtered bytes (summed in lanes: zlib's adler32 is scalar),
    // and their count: the stream's checksum joins the pieces' sums (combineAdler).
    uint32_t adler = 1;
    size_t filteredBytes = 0;
    // Deflated on its own, ending on a byte boundary (but the last piece, which ends with the
    // final block), so that the pieces simply join. The first carries the zlib header, the last
    // the checksum (appendChecksum, once every piece's sum is known).
    std::vector<uint8_t> compressed;
    // The CRC of the piece's IDAT chunk, taken by its task (but the last piece's, which the
    // checksum joins later, and pieces too large for one chunk).
    std::optional<uint32_t> crc;
};

// Pieces [begin, end) encoded into out[0, end - begin), one task per piece on `threads` (as for
// parallelFor), from the rows rowAt gives (rows [filterFrom(begin) - 1, endRow(end - 1))).
// `scratches` is kept by the caller from call to call; it is sized here.
void encodePieces(const RowLayout& rows, const PieceLayout& pieces, const PngRowSource& rowAt,
                  size_t begin, size_t end, int threads, std::vector<PieceScratch>& scratches,
                  std::span<EncodedPiece> out);

// The stream's checksum so far (1 before any piece) continued by the next piece's.
uint32_t combineAdler(uint32_t adler, const EncodedPiece& piece);

// The zlib stream's checksum, the pieces' sums joined, at the end of the last piece.
void appendChecksum(EncodedPiece& last, uint32_t adler);

// The file's parts, in this order: signature and IHDR; each piece as IDAT chunks (one, or
// several where it is too large for one); IEND.
void writeHeader(const PngFormat& format, const PngSink& sink);
void writePiece(const EncodedPiece& piece, const PngSink& sink);
void writeEnd(const PngSink& sink);

// The bytes writeHeader, writePiece and writeEnd give, all together.
size_t pngFileBytes(std::span<const EncodedPiece> pieces);

}  // namespace quaternia::png_pieces
