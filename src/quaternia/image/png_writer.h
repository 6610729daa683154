// Our own PNG writer, in place of libpng's: libpng filters and deflates one row after another on
// one thread, which made writing a 1080p frame a fifth of a whole render command. Here the rows
// are cut into fixed pieces that are filtered and deflated in parallel (as pigz does), and the
// pieces, joined, form one ordinary zlib stream that any decoder reads (png_pieces.h; the same
// pieces are written as their rows arrive by PngStreamWriter, png_stream_writer.h).
//
// The file is always the same bytes for the same samples, whatever the number of threads: the
// pieces are cut from the image's layout alone, and each is compressed on its own from the same
// inputs. Callers compare PNGs byte for byte (explore_server_test, plane_render_test).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace quaternia {

// The colour types this writer produces; the values are PNG's.
enum class PngColorType : uint8_t { Gray = 0, Rgb = 2, Rgba = 6 };

struct PngFormat {
    int width = 0, height = 0;
    int bitDepth = 8;  // 8 or 16 bits per sample
    PngColorType colorType = PngColorType::Rgba;
};

// Samples per pixel.
inline int pngChannels(PngColorType type) {
    return type == PngColorType::Gray ? 1 : type == PngColorType::Rgb ? 3 : 4;
}

// Bytes of one unfiltered row: width * channels * bitDepth / 8.
inline size_t pngRowBytes(const PngFormat& format) {
    return size_t(format.width) * size_t(pngChannels(format.colorType)) *
           size_t(format.bitDepth / 8);
}

// The rows in PNG's filtering, compressed: every row Paeth-filtered, the rows cut into pieces of
// about 256 KiB of filtered bytes, each piece deflated with runs as its only matches
// (deflate_runs.h) and written as one IDAT chunk. `samples` holds the rows back to back in PNG's
// byte order (16-bit samples big-endian), height * pngRowBytes(format) bytes. `threads` as for
// parallelFor: 0 is every core; the bytes do not depend on it. Throws std::invalid_argument for
// an empty image, a bit depth other than 8 or 16, or a wrong number of samples;
// std::bad_alloc when memory runs out.
std::vector<uint8_t> writePngBytes(const PngFormat& format, std::span<const uint8_t> samples,
                                   int threads = 0);

// An upper bound of the size of the file writePngBytes or writePngRows makes of `format`, for
// memory budgets: deflateRuns stores a block when coding would make it longer, so the file is
// the filtered rows plus block and chunk headers (a few bytes per 64 KiB) and the fixed chunks
// (signature, IHDR, IEND).
uint64_t pngBytesBound(const PngFormat& format);

// Row y's samples (pngRowBytes(format) bytes, as above): either a pointer into the caller's own
// rows, or `scratch` (room for one row) filled and returned. Called from several threads at
// once, and for some rows more than once, so it must be a pure function of y.
using PngRowSource = std::function<const uint8_t*(size_t y, uint8_t* scratch)>;

// Where an encoder's bytes go: each call appends the next bytes of the file.
using PngSink = std::function<void(std::span<const uint8_t> bytes)>;

// writePngBytes with the rows made as they are needed, piece by piece on every core (a frame's
// quantised samples then never exist whole: a 1080p frame's 6 MB and two passes over them less).
// The same bytes as writePngBytes of the same rows. Throws as writePngBytes, but for the
// number of samples.
std::vector<uint8_t> writePngRows(const PngFormat& format, const PngRowSource& rowAt,
                                  int threads = 0);

}  // namespace quaternia
