#include "quaternia/image/png_stream_writer.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace quaternia {

using namespace png_pieces;

PngStreamWriter::PngStreamWriter(const PngFormat& format, PngSink sink, int threads)
    : format_(format), sink_(std::move(sink)), threads_(threads) {
    checkFormat(format_);
    rowBytes_ = pngRowBytes(format_);
    writeHeader(format_, sink_);
}

void PngStreamWriter::addRows(std::span<const uint8_t> rows, size_t count) {
    if (finished_) throw std::logic_error("PNG rows added after the stream was finished");
    if (rows.size() / rowBytes_ != count || rows.size() % rowBytes_ != 0)
        throw std::invalid_argument("PNG rows do not match their count and the image's width");
    const RowLayout layout(format_);
    if (count > layout.height - rowsAdded_)
        throw std::invalid_argument("more PNG rows than the image's height");
    const size_t spanFirst = rowsAdded_;
    rowsAdded_ += count;

    const PieceLayout pieces(layout.height, layout.filteredRowBytes);
    size_t ready = nextPiece_;  // the pieces [nextPiece_, ready) have all their rows now
    while (ready < pieces.count && pieces.endRow(ready, layout.height) <= rowsAdded_)
        ++ready;
    if (ready > nextPiece_) {
        // The rows before the caller's come from kept_, which holds every one a piece may ask
        // for (keepRows); nothing is copied for pieces that the caller's rows complete.
        const PngRowSource rowAt = [&](size_t y, uint8_t*) {
            return y >= spanFirst ? rows.data() + (y - spanFirst) * rowBytes_
                                  : kept_.data() + (y - keptFirst_) * rowBytes_;
        };
        std::vector<EncodedPiece> encoded(ready - nextPiece_);
        encodePieces(layout, pieces, rowAt, nextPiece_, ready, threads_, scratches_, encoded);
        for (EncodedPiece& piece : encoded) {
            adler_ = combineAdler(adler_, piece);
            if (nextPiece_ + 1 == pieces.count)
                last_ = std::move(piece);  // its chunk needs the whole stream's checksum
            else
                writePiece(piece, sink_);
            ++nextPiece_;
        }
    }
    keepRows(rows, spanFirst);
}

void PngStreamWriter::keepRows(std::span<const uint8_t> rows, size_t spanFirst) {
    const PieceLayout pieces(size_t(format_.height), rowBytes_ + 1);
    size_t from = rowsAdded_;  // nothing, once every piece is encoded
    if (nextPiece_ < pieces.count) {
        const size_t first = pieces.firstRow(nextPiece_);
        from = first - std::min<size_t>(first, 2);
    }
    // Rows before `from` leave kept_; the caller's rows from `from` on join it.
    const size_t keptEnd = keptFirst_ + kept_.size() / rowBytes_;
    const size_t drop = std::min(keptEnd, std::max(from, keptFirst_)) - keptFirst_;
    kept_.erase(kept_.begin(), kept_.begin() + std::ptrdiff_t(drop * rowBytes_));
    keptFirst_ += drop;
    if (kept_.empty()) keptFirst_ = std::max(from, spanFirst);
    const size_t takeFrom = std::max(from, spanFirst);
    kept_.insert(kept_.end(), rows.begin() + std::ptrdiff_t((takeFrom - spanFirst) * rowBytes_),
                 rows.end());
}

void PngStreamWriter::finish() {
    if (finished_) throw std::logic_error("the PNG stream was finished twice");
    if (rowsAdded_ != size_t(format_.height) || !last_)
        throw std::logic_error("the PNG stream is missing " +
                               std::to_string(size_t(format_.height) - rowsAdded_) + " rows");
    finished_ = true;
    appendChecksum(*last_, adler_);
    writePiece(*last_, sink_);
    writeEnd(sink_);
    last_.reset();
    kept_ = {};
}

}  // namespace quaternia
