// SIMD lanes of PNG encoding (png_io.cpp, png_writer.cpp): quantising float pixels to samples,
// the opacity check, the Paeth filter and the zlib stream's checksum, compiled per instruction set
// by Highway like shading_lanes.h and chosen at run time. Each gives exactly the bytes of the
// scalar formula it replaces, which png_lanes_test.cpp keeps as its reference.
#pragma once

#include <cstddef>
#include <cstdint>

namespace quaternia {

// PNG samples of `pixels` RGBA pixels (four floats each, packed): r, g, b and, withAlpha, a,
// each clamped to [0, 1] (NaN to 0) and rounded to the nearest of 0 .. 2^bitDepth - 1 (halves
// up), exactly as uint32_t(double(clamped) * max + 0.5). 16-bit samples are big-endian, as PNG
// stores them. bitDepth is 8 or 16; `out` has room for pixels * channels * bitDepth / 8 bytes.
void quantisePngSamples(const float* rgba, size_t pixels, int bitDepth, bool withAlpha,
                        uint8_t* out);

// Whether the alpha of every one of `pixels` RGBA pixels quantises (as above) to the largest
// sample of bitDepth bits, so that the image may be written without alpha.
bool allAlphaQuantiseToMax(const float* rgba, size_t pixels, int bitDepth);

// The filtered bytes of one PNG scanline under the Paeth filter (PNG spec 9.4), the filter type
// byte not included: each byte of `row` minus its prediction from the unfiltered bytes to the
// left (a), above (b) and above left (c), whichever is nearest to a + b - c, ties going to a,
// then b. Left of the first pixel counts as 0; `previous` is the row above (zeros above the
// first row). All three spans hold rowBytes bytes; `out` must not overlap the others.
// bytesPerPixel is 1 to 8, as in PNG's formats.
void filterPaethRow(const uint8_t* row, const uint8_t* previous, size_t rowBytes,
                    size_t bytesPerPixel, uint8_t* out);

// The Adler-32 checksum (RFC 1950) of `size` bytes, continued from `adler` (1 before any byte):
// the value zlib's adler32_z gives, whose loop (zlib 1.2) is scalar.
uint32_t adler32Update(uint32_t adler, const uint8_t* bytes, size_t size);

}  // namespace quaternia
