// Reading high-dynamic-range images for environment maps: Radiance RGBE files (.hdr, .pic) and
// OpenEXR, and writing Radiance files so that the project can generate and ship maps.
//
// Radiance: Greg Ward, "Real Pixels", Graphics Gems II (1991), and "Radiance File Formats" in
// the Radiance reference manual: a text header of lines ended by '\n' and closed
// by an empty line, a resolution line, then one scanline after another, each either new-style
// run-length encoded (2, 2, width >> 8, width & 255, then the four components one after the
// other, each as runs and literals) or flat (4 bytes a pixel, with Ward's old-style runs: a pixel
// 1, 1, 1, n repeats the previous pixel n << (8 * the number of such pixels just before) times).
// OpenEXR: the "OpenEXR File Layout" document, read through the OpenEXR 3.1 library.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "quaternia/util/memory_budget.h"

namespace quaternia {

// A linear RGB image of floats, row-major, top row first: rgb[3 * (y * width + x) + channel].
struct HdrImage {
    int width = 0, height = 0;
    std::vector<float> rgb;
};

// Reads a Radiance RGBE file or an OpenEXR file, chosen by the file's first bytes, not its name:
// "#?RADIANCE" or "#?RGBE" (Radiance), or 0x76 0x2f 0x31 0x01 (OpenEXR).
//
// Radiance: FORMAT must be 32-bit_rle_rgbe (XYZE is refused) and the resolution line
// "-Y H +X W" (top row first, left to right; the other seven orientations are refused). Each
// EXPOSURE=e line of the header says that the values were multiplied by e after they were
// computed; the values read are divided by the product of them all, so they are the scene's.
// Other header lines (comments, SOFTWARE, PRIMARIES, COLORCORR, GAMMA) are ignored. A value is
// (mantissa + 0.5) / 256 * 2^(exponent - 128), or 0 for exponent 0: Ward's colr_color, which
// puts each value in the middle of the interval that the encoder's truncation maps to its byte.
//
// OpenEXR: the first part of the file; its R, G and B channels (half or float), or, without
// those, a Y channel read as grey (R = G = B = Y); luminance/chroma (Y, RY, BY) files and deep
// files are refused. Scanline and tiled files alike; the data window is the image (the display
// window is ignored), its top row first. Colours are taken as they are stored (the
// chromaticities attribute, if any, is ignored: Rec. 709 primaries are assumed).
//
// Values that are NaN, infinite or negative are clamped to 0 (environment lighting must be
// finite and non-negative; such values come from broken renders or half-float overflow).
//
// `key` is the scene key that named the file (e.g. "environment.map"). Errors throw
// UserError(key, message), the message one line naming the key and the file:
// "environment.map: 'sky.png' is not an HDR image (Radiance .hdr or OpenEXR)",
// "environment.map: 'x.hdr': no such file", "environment.map: 'x.hdr' is truncated",
// "environment.map: 'x.hdr': cannot read (permission denied)", a corrupt or unsupported file, an
// EXR without R, G, B or Y channels, a width or height <= 0 or > 65536. Before the file is read
// and again before the pixels are allocated, requireMemory(...) (memory_budget.h) checks the
// file's size, then the pixels' (plus, for OpenEXR, an estimate of the library's buffers for
// one block of rows or tiles), against `budget`; it throws MemoryLimitError.
HdrImage readHdrImage(const std::string& path, const std::string& key, const MemoryBudget& budget);

// The same from bytes in memory (path only for messages).
HdrImage decodeHdrImage(const std::vector<uint8_t>& bytes, const std::string& path,
                        const std::string& key, const MemoryBudget& budget);

// A Radiance RGBE file's bytes: header "#?RADIANCE", FORMAT=32-bit_rle_rgbe, "-Y H +X W", then
// new-style run-length encoded scanlines where the width is 8..32767 (the range that the
// scanline's marker can hold), else flat ones. Each pixel: the largest channel v = m * 2^e with
// m in [0.5, 1) (frexp) sets the exponent byte e + 128, and each channel c the mantissa byte
// floor(c * 2^(8 - e)) (Ward's truncation), so that readHdrImage returns the largest channel
// within one part in 256 (relative) and the others within 1/256 of the largest. Values that are
// NaN, infinite, negative or below 2^-128 are written as 0; those of 2^127 or more saturate.
// Throws std::invalid_argument for an empty image or rgb of the wrong size.
std::vector<uint8_t> encodeRadianceHdr(const HdrImage& image);

}  // namespace quaternia
