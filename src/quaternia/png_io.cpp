// libpng reports an error by calling our error handler, which must not return: it longjmps back
// to the last setjmp on png_jmpbuf. C++ allows a longjmp only where a throw to the same place
// would destroy no objects with non-trivial destructors ([support.runtime]), so every function
// that libpng can longjmp out of (the setjmp functions writeImage, readHeader and readRows, and
// the I/O callbacks) holds only trivially destructible locals; the output vector, the row
// buffers and the RAII owners of the png structs live in their callers, which libpng never
// sees. Callback code that may throw (vector growth) runs in a separate noexcept function and
// only reports failure, so no exception crosses libpng's C frames either.
#include "png_io.h"

#include <png.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <new>
#include <stdexcept>
#include <system_error>

#include "util/atomic_file.h"
#include "util/error.h"

namespace quaternia {

namespace {

// Larger sides are refused when reading, before any memory is allocated for them.
constexpr png_uint_32 kMaxReadSide = 1u << 16;
constexpr uint64_t kMaxReadPixels = uint64_t(1) << 28;

struct ErrorState {
    char message[256] = "unknown libpng error";
};

[[noreturn]] void onPngError(png_structp png, png_const_charp message) {
    auto* state = static_cast<ErrorState*>(png_get_error_ptr(png));
    std::snprintf(state->message, sizeof state->message, "%s", message);
    png_longjmp(png, 1);
}

void onPngWarning(png_structp, png_const_charp) {}  // library code never prints

// ---- encoding ----------------------------------------------------------------------------

// Clamped to [0, 1] (NaN to 0), then rounded to the nearest of 0 .. maxValue. In double: a
// float times 65535 keeps too few fractional bits to round reliably.
uint16_t quantise(float value, uint32_t maxValue) {
    if (!(value > 0.0f)) return 0;
    if (value >= 1.0f) return uint16_t(maxValue);
    return uint16_t(double(value) * double(maxValue) + 0.5);
}

// Appends one quantised sample, big-endian as PNG stores it.
uint8_t* putSample(uint8_t* out, float value, int bitDepth) {
    if (bitDepth == 8) {
        *out++ = uint8_t(quantise(value, 255));
    } else {
        uint16_t v = quantise(value, 65535);
        *out++ = uint8_t(v >> 8);
        *out++ = uint8_t(v & 0xff);
    }
    return out;
}

struct WriteSink {
    std::vector<uint8_t>* bytes;
};

bool appendBytes(std::vector<uint8_t>* bytes, const uint8_t* data, size_t length) noexcept {
    try {
        bytes->insert(bytes->end(), data, data + length);
        return true;
    } catch (...) {
        return false;
    }
}

void writeCallback(png_structp png, png_bytep data, size_t length) {
    auto* sink = static_cast<WriteSink*>(png_get_io_ptr(png));
    if (!appendBytes(sink->bytes, data, length)) png_error(png, "out of memory");
}

void flushCallback(png_structp) {}

class PngWriter {
  public:
    explicit PngWriter(ErrorState* errors) {
        png_ = png_create_write_struct(PNG_LIBPNG_VER_STRING, errors, onPngError, onPngWarning);
        if (png_) info_ = png_create_info_struct(png_);
        if (!png_ || !info_) {
            png_destroy_write_struct(&png_, &info_);
            throw std::bad_alloc();
        }
    }
    ~PngWriter() { png_destroy_write_struct(&png_, &info_); }
    PngWriter(const PngWriter&) = delete;
    PngWriter& operator=(const PngWriter&) = delete;

    png_structp png() const { return png_; }
    png_infop info() const { return info_; }

  private:
    png_structp png_ = nullptr;
    png_infop info_ = nullptr;
};

struct EncodeJob {
    png_uint_32 width, height;
    int bitDepth, colorType;
    png_bytepp rows;
};

// Trivially destructible locals only: libpng may longjmp to the setjmp here.
bool writeImage(png_structp png, png_infop info, const EncodeJob& job, WriteSink* sink) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_set_write_fn(png, sink, writeCallback, flushCallback);
    png_set_IHDR(png, info, job.width, job.height, job.bitDepth, job.colorType, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    // Speed over the last few percent of size: zlib's level 1 with the Paeth filter is several
    // times faster than the defaults (the whole adaptive filter search at level 6) and makes
    // files about 10% larger on renders; encoding a 1080p frame otherwise costs a third of a
    // render.
    png_set_compression_level(png, 1);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_PAETH);
    png_write_info(png, info);
    png_write_image(png, job.rows);
    png_write_end(png, nullptr);
    return true;
}

// `samples` holds the rows back to back, already in PNG's byte order.
std::vector<uint8_t> encodeSamples(int width, int height, int bitDepth, int colorType,
                                   std::vector<uint8_t>& samples) {
    if (width <= 0 || height <= 0)
        throw std::invalid_argument("cannot encode an empty image as PNG");
    const size_t rowBytes = samples.size() / size_t(height);
    std::vector<png_bytep> rows(static_cast<size_t>(height));
    for (size_t y = 0; y < rows.size(); ++y)
        rows[y] = samples.data() + y * rowBytes;

    ErrorState errors;
    PngWriter writer(&errors);
    std::vector<uint8_t> bytes;
    bytes.reserve(samples.size() / 2 + 1024);
    WriteSink sink{&bytes};
    const EncodeJob job{png_uint_32(width), png_uint_32(height), bitDepth, colorType, rows.data()};
    if (!writeImage(writer.png(), writer.info(), job, &sink))
        throw std::runtime_error(std::string("cannot encode PNG: ") + errors.message);
    return bytes;
}

// ---- decoding ----------------------------------------------------------------------------

struct ReadSource {
    const uint8_t* data;
    size_t size, offset;
};

void readCallback(png_structp png, png_bytep out, size_t length) {
    auto* source = static_cast<ReadSource*>(png_get_io_ptr(png));
    if (length > source->size - source->offset) png_error(png, "the file is truncated");
    std::memcpy(out, source->data + source->offset, length);
    source->offset += length;
}

class PngReader {
  public:
    explicit PngReader(ErrorState* errors) {
        png_ = png_create_read_struct(PNG_LIBPNG_VER_STRING, errors, onPngError, onPngWarning);
        if (png_) info_ = png_create_info_struct(png_);
        if (!png_ || !info_) {
            png_destroy_read_struct(&png_, &info_, nullptr);
            throw std::bad_alloc();
        }
    }
    ~PngReader() { png_destroy_read_struct(&png_, &info_, nullptr); }
    PngReader(const PngReader&) = delete;
    PngReader& operator=(const PngReader&) = delete;

    png_structp png() const { return png_; }
    png_infop info() const { return info_; }

  private:
    png_structp png_ = nullptr;
    png_infop info_ = nullptr;
};

struct DecodeLayout {
    png_uint_32 width, height;
    size_t rowBytes;
};

// Reads the header and asks libpng for 16-bit RGBA whatever the file holds: palettes, low bit
// depths and tRNS expand, gray becomes RGB, 8 bits become 16 (v * 257, so v / 255 is kept
// exactly), and a file without alpha gets an opaque one. Trivially destructible locals only.
bool readHeader(png_structp png, png_infop info, ReadSource* source, DecodeLayout* layout) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_set_read_fn(png, source, readCallback);
    png_set_user_limits(png, kMaxReadSide, kMaxReadSide);
    png_read_info(png, info);
    const int colorType = png_get_color_type(png, info);
    const bool hasAlpha =
        (colorType & PNG_COLOR_MASK_ALPHA) || png_get_valid(png, info, PNG_INFO_tRNS);
    png_set_expand(png);
    png_set_expand_16(png);
    png_set_gray_to_rgb(png);
    if (!hasAlpha) png_set_add_alpha(png, 0xffff, PNG_FILLER_AFTER);
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    if (png_get_channels(png, info) != 4 || png_get_bit_depth(png, info) != 16)
        png_error(png, "unsupported pixel format");
    layout->width = png_get_image_width(png, info);
    layout->height = png_get_image_height(png, info);
    layout->rowBytes = png_get_rowbytes(png, info);
    if (uint64_t(layout->width) * layout->height > kMaxReadPixels)
        png_error(png, "the image is too large");
    return true;
}

// Trivially destructible locals only.
bool readRows(png_structp png, png_bytepp rows) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_image(png, rows);
    png_read_end(png, nullptr);
    return true;
}

std::string errnoText(int error) {
    return std::generic_category().message(error);
}

// The whole file; on failure returns false with errno's reason in `reason`.
bool readFileBytes(const std::string& path, std::vector<uint8_t>& bytes, std::string& reason) {
    std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "rb"), std::fclose);
    if (!file) {
        reason = errnoText(errno);
        return false;
    }
    uint8_t buffer[1 << 16];
    size_t got;
    while ((got = std::fread(buffer, 1, sizeof buffer, file.get())) > 0)
        bytes.insert(bytes.end(), buffer, buffer + got);
    if (std::ferror(file.get())) {
        reason = errnoText(errno);
        return false;
    }
    return true;
}

}  // namespace

std::vector<uint8_t> encodePng(const Image& image, int bitDepth) {
    if (bitDepth != 8 && bitDepth != 16)
        throw std::invalid_argument("PNG bit depth must be 8 or 16, got " +
                                    std::to_string(bitDepth));
    std::vector<uint8_t> samples(image.pixels().size() * 4 * size_t(bitDepth / 8));
    uint8_t* out = samples.data();
    for (const Rgba& p : image.pixels()) {
        out = putSample(out, p.r, bitDepth);
        out = putSample(out, p.g, bitDepth);
        out = putSample(out, p.b, bitDepth);
        out = putSample(out, p.a, bitDepth);
    }
    return encodeSamples(image.width(), image.height(), bitDepth, PNG_COLOR_TYPE_RGB_ALPHA,
                         samples);
}

std::vector<uint8_t> encodeGrayPng16(const GrayImage& image) {
    std::vector<uint8_t> samples(image.pixels().size() * 2);
    uint8_t* out = samples.data();
    for (float v : image.pixels())
        out = putSample(out, v, 16);
    return encodeSamples(image.width(), image.height(), 16, PNG_COLOR_TYPE_GRAY, samples);
}

void writePng(const std::string& path, const Image& image, int bitDepth) {
    writeFileAtomically(path, encodePng(image, bitDepth));
}

void writeGrayPng16(const std::string& path, const GrayImage& image) {
    writeFileAtomically(path, encodeGrayPng16(image));
}

Image decodePng(std::span<const uint8_t> bytes) {
    ErrorState errors;
    PngReader reader(&errors);
    ReadSource source{bytes.data(), bytes.size(), 0};
    DecodeLayout layout{};
    if (!readHeader(reader.png(), reader.info(), &source, &layout))
        throw std::runtime_error(errors.message);

    std::vector<uint8_t> samples(layout.rowBytes * layout.height);
    std::vector<png_bytep> rows(layout.height);
    for (size_t y = 0; y < rows.size(); ++y)
        rows[y] = samples.data() + y * layout.rowBytes;
    if (!readRows(reader.png(), rows.data())) throw std::runtime_error(errors.message);

    Image image(int(layout.width), int(layout.height));
    for (int y = 0; y < image.height(); ++y) {
        const uint8_t* in = rows[size_t(y)];
        for (int x = 0; x < image.width(); ++x) {
            float v[4];
            for (float& c : v) {
                c = float((unsigned(in[0]) << 8) | in[1]) / 65535.0f;
                in += 2;
            }
            image.at(x, y) = Rgba{v[0], v[1], v[2], v[3]};
        }
    }
    return image;
}

Image readPng(const std::string& path) {
    std::vector<uint8_t> bytes;
    std::string reason;
    if (!readFileBytes(path, bytes, reason))
        throw UserError(path, "cannot read PNG '" + path + "': " + reason);
    try {
        return decodePng(bytes);
    } catch (const std::runtime_error& e) {
        throw UserError(path, "cannot read PNG '" + path + "': " + e.what());
    }
}

}  // namespace quaternia
