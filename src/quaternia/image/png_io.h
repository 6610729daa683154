// PNG files: RGBA (or RGB, when opaque) images at 8 or 16 bits per channel, 16-bit gray depth
// passes, and reading any PNG back as an Image. Encoding works to memory with our own parallel
// writer (png_writer.h), so the same bytes can go to a file (atomically, through AtomicFile) or
// over HTTP; decoding goes through libpng, which also reads a file row by row as it is stored
// (PngRowReader).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "quaternia/image/image.h"
#include "quaternia/image/png_writer.h"

namespace quaternia {

// RGBA, `bitDepth` 8 or 16 bits per channel (else std::invalid_argument). Each value is clamped
// to [0, 1] (NaN counts as 0) and rounded: floor(v * 255 + 0.5), or floor(v * 65535 + 0.5).
// The colour values are written as they are: they are display values already. When every
// alpha rounds to the maximum, the file is RGB (colour type 2) instead: it decodes the same.
// The bytes depend on the image alone, not on the number of cores. `opaque`: the caller knows
// that every alpha is 1 (an opaque render), which spares the check over the whole image.
std::vector<uint8_t> encodePng(const Image& image, int bitDepth, bool opaque = false);

// One 16-bit gray channel, values clamped to [0, 1] and rounded as above.
std::vector<uint8_t> encodeGrayPng16(const GrayImage& image);
// `count` values as encodeGrayPng16 stores them: 2 bytes each, big-endian.
void quantiseGray16(const float* values, size_t count, uint8_t* out);

// Encodes, then writes through AtomicFile: the file at `path` is replaced whole or not at all.
// Throws UserError(path, "cannot write '<path>': <reason>").
void writePng(const std::string& path, const Image& image, int bitDepth);
void writeGrayPng16(const std::string& path, const GrayImage& image);

// Any PNG (gray, gray + alpha, RGB, RGBA or palette; 1 to 16 bits; interlaced or not) as an
// Image of values in [0, 1]: gray fills r, g and b alike; alpha is 1 where the file has none
// (a tRNS chunk gives alpha as usual). Gamma chunks are ignored: the values are taken as
// display values. Throws std::runtime_error with libpng's reason for malformed data.
Image decodePng(std::span<const uint8_t> bytes);

// Reads and decodes a file. Throws UserError(path, "cannot read PNG '<path>': <reason>").
Image readPng(const std::string& path);

// A PNG file's rows one at a time, as stored: 8- or 16-bit samples (16-bit ones big-endian),
// nothing transformed, so that a file from writePngRows reads back as the rows given to it. For
// non-interlaced gray, RGB or RGBA files of 8 or 16 bits (the formats PngFormat names), read
// with one row in memory. Every error (the file, a format it does not read, malformed data)
// is a std::runtime_error.
class PngRowReader {
  public:
    // Opens the file and reads its header.
    explicit PngRowReader(const std::string& path);
    ~PngRowReader();
    PngRowReader(const PngRowReader&) = delete;
    PngRowReader& operator=(const PngRowReader&) = delete;

    const PngFormat& format() const;
    size_t rowsRead() const;

    // The next row into `row`, which holds exactly pngRowBytes(format()) bytes. After the last
    // one the rest of the file is read and checked too. Throws past the last row.
    void readRow(std::span<uint8_t> row);

  private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace quaternia
