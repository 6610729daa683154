// A PNG written as its rows arrive, band after band, without the whole image ever in memory:
// the same bytes as writePngBytes of the same rows (png_writer.h), whatever the bands and the
// number of threads, because both encode the same pieces (png_pieces.h). Each piece's IDAT
// chunk goes to the sink as soon as its rows are in; only the last waits for the stream's
// checksum. Memory: the rows of the piece not yet complete (about 256 KiB of samples) and the
// two rows before it, plus, while a call runs, one piece's buffers per thread.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "quaternia/image/png_pieces.h"
#include "quaternia/image/png_writer.h"

namespace quaternia {

class PngStreamWriter {
  public:
    // Writes the signature and IHDR to `sink` at once. `threads` as for parallelFor (0 is every
    // core): whole pieces that arrive together are encoded in parallel. Throws
    // std::invalid_argument for an empty image or a bit depth other than 8 or 16.
    PngStreamWriter(const PngFormat& format, PngSink sink, int threads = 0);
    PngStreamWriter(const PngStreamWriter&) = delete;
    PngStreamWriter& operator=(const PngStreamWriter&) = delete;

    // The next `count` rows, in order, back to back in PNG's byte order (16-bit samples
    // big-endian): count * pngRowBytes(format) bytes, which the writer does not keep a
    // reference to. Throws std::invalid_argument when `rows` has another size or the image
    // would have more than its height, std::logic_error after finish(). After any exception
    // (the sink's too) the file is unfinished and the writer is of no more use.
    void addRows(std::span<const uint8_t> rows, size_t count);

    // Writes the last piece, with the stream's checksum, and IEND. Throws std::logic_error
    // when rows are missing or when called twice.
    void finish();

    size_t rowsAdded() const { return rowsAdded_; }
    const PngFormat& format() const { return format_; }

  private:
    // The rows of `rows` (rows [spanFirst, rowsAdded_)) and of kept_ that are still needed.
    void keepRows(std::span<const uint8_t> rows, size_t spanFirst);

    PngFormat format_;
    PngSink sink_;
    int threads_;
    size_t rowBytes_, rowsAdded_ = 0;
    size_t nextPiece_ = 0;  // the first piece not yet encoded
    uint32_t adler_ = 1;    // the checksum of the pieces encoded so far
    bool finished_ = false;
    // Rows [keptFirst_, keptFirst_ + kept_.size() / rowBytes_): those of the pieces not yet
    // encoded and the two rows before the first of them (png_pieces::PieceLayout::filterFrom).
    std::vector<uint8_t> kept_;
    size_t keptFirst_ = 0;
    std::vector<png_pieces::PieceScratch> scratches_;
    // The last piece, encoded once its rows are in, written by finish().
    std::optional<png_pieces::EncodedPiece> last_;
};

}  // namespace quaternia
