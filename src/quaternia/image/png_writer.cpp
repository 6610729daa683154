#include "quaternia/image/png_writer.h"

#include <stdexcept>

#include "quaternia/image/png_pieces.h"

namespace quaternia {

uint64_t pngBytesBound(const PngFormat& format) {
    const uint64_t filtered = uint64_t(format.height) * (1 + pngRowBytes(format));
    return filtered + filtered / 1024 + 4096;
}

std::vector<uint8_t> writePngBytes(const PngFormat& format, std::span<const uint8_t> samples,
                                   int threads) {
    png_pieces::checkFormat(format);
    const size_t rowBytes = pngRowBytes(format);
    if (samples.size() != rowBytes * size_t(format.height))
        throw std::invalid_argument("PNG samples do not match the image's size");
    return writePngRows(
        format, [&](size_t y, uint8_t*) { return samples.data() + y * rowBytes; }, threads);
}

std::vector<uint8_t> writePngRows(const PngFormat& format, const PngRowSource& rowAt, int threads) {
    using namespace png_pieces;
    checkFormat(format);
    const RowLayout rows(format);
    const PieceLayout pieces(rows.height, rows.filteredRowBytes);
    // Each piece is filtered and deflated by one task, from the rows the source gives it: the
    // samples never exist as a whole image.
    std::vector<EncodedPiece> encoded(pieces.count);
    std::vector<PieceScratch> scratches;
    encodePieces(rows, pieces, rowAt, 0, pieces.count, threads, scratches, encoded);
    uint32_t adler = 1;
    for (const EncodedPiece& piece : encoded)
        adler = combineAdler(adler, piece);
    appendChecksum(encoded.back(), adler);

    std::vector<uint8_t> png;
    png.reserve(pngFileBytes(encoded));
    const PngSink append = [&](std::span<const uint8_t> bytes) {
        png.insert(png.end(), bytes.begin(), bytes.end());
    };
    writeHeader(format, append);
    for (const EncodedPiece& piece : encoded)
        writePiece(piece, append);
    writeEnd(append);
    return png;
}

}  // namespace quaternia
