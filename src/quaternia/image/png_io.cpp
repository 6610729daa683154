// Encoding: the samples are quantised here and handed to our own writer (png_writer.h).
// Decoding, through libpng, is png_read.cpp's.
#include "quaternia/image/png_io.h"

#include <atomic>
#include <stdexcept>
#include <string>

#include "quaternia/image/png_lanes.h"
#include "quaternia/image/png_writer.h"
#include "quaternia/util/atomic_file.h"
#include "quaternia/util/parallel.h"

namespace quaternia {

namespace {

// Pixels per parallel item of the opacity check: small images stay on the calling thread.
constexpr int64_t kAlphaBlockPixels = 16384;

// Clamped to [0, 1] (NaN to 0), then rounded to the nearest of 0 .. 65535, big-endian as PNG
// stores it; returns the sample's end. In double: a float times 65535 keeps too few fractional
// bits to round reliably. The grey depth pass's formula; colour images are quantised in lanes
// by quantisePngSamples (png_lanes.h), to exactly what this gives.
uint8_t* putSample16(uint8_t* out, float value) {
    // Selects rather than branches, so that the loop over pixels vectorises.
    const float clamped = value > 0.0f ? (value < 1.0f ? value : 1.0f) : 0.0f;
    const uint32_t v = uint32_t(double(clamped) * 65535.0 + 0.5);
    *out++ = uint8_t(v >> 8);
    *out++ = uint8_t(v & 0xff);
    return out;
}

// Whether every pixel's alpha quantises to the largest sample of bitDepth bits: checked in
// blocks on every core; a block with a lower one ends the search.
bool alphaIsAllMax(const Image& image, int bitDepth) {
    static_assert(sizeof(Rgba) == 4 * sizeof(float), "Rgba is four packed floats");
    const Rgba* pixels = image.pixels().data();
    const int64_t count = int64_t(image.pixels().size());
    std::atomic<bool> lower{false};
    ParallelOptions options;
    options.chunkSize = kAlphaBlockPixels;
    parallelFor(count, options, [&](int64_t begin, int64_t end, int) {
        if (lower.load(std::memory_order_relaxed)) return;
        if (!allAlphaQuantiseToMax(&pixels[begin].r, size_t(end - begin), bitDepth))
            lower.store(true, std::memory_order_relaxed);
    });
    return !lower.load();
}

}  // namespace

std::vector<uint8_t> encodePng(const Image& image, int bitDepth, bool knownOpaque) {
    if (bitDepth != 8 && bitDepth != 16)
        throw std::invalid_argument("PNG bit depth must be 8 or 16, got " +
                                    std::to_string(bitDepth));
    // An alpha channel that is all maximum says nothing: RGB is a quarter less to compress and
    // decodes the same (opaque renders, plane images).
    const bool opaque = knownOpaque || alphaIsAllMax(image, bitDepth);
    const PngFormat format{image.width(), image.height(), bitDepth,
                           opaque ? PngColorType::Rgb : PngColorType::Rgba};
    const size_t width = size_t(image.width());
    // Each row quantised as the writer asks for it.
    return writePngRows(format, [&](size_t y, uint8_t* out) {
        quantisePngSamples(&image.at(0, int(y)).r, width, bitDepth, !opaque, out);
        return static_cast<const uint8_t*>(out);
    });
}

void quantiseGray16(const float* values, size_t count, uint8_t* out) {
    for (size_t i = 0; i < count; ++i)
        out = putSample16(out, values[i]);
}

std::vector<uint8_t> encodeGrayPng16(const GrayImage& image) {
    const PngFormat format{image.width(), image.height(), 16, PngColorType::Gray};
    const float* values = image.pixels().data();
    const size_t width = size_t(image.width());
    return writePngRows(format, [&](size_t y, uint8_t* out) {
        quantiseGray16(values + y * width, width, out);
        return static_cast<const uint8_t*>(out);
    });
}

void writePng(const std::string& path, const Image& image, int bitDepth) {
    writeFileAtomically(path, encodePng(image, bitDepth));
}

void writeGrayPng16(const std::string& path, const GrayImage& image) {
    writeFileAtomically(path, encodeGrayPng16(image));
}

}  // namespace quaternia
