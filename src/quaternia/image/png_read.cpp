// Decoding PNGs through libpng (png_io.h); encoding is png_io.cpp's.
//
// libpng reports an error by calling our error handler, which must not return: it longjmps back
// to the last setjmp on png_jmpbuf. C++ allows a longjmp only where a throw to the same place
// would destroy no objects with non-trivial destructors ([support.runtime]), so every function
// that libpng can longjmp out of (the setjmp functions readHeader and readRows, and the read
// callback) holds only trivially destructible locals; the row buffers and the RAII owner of the
// png structs live in their callers, which libpng never sees.
#include "quaternia/image/png_io.h"

#include <png.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <new>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "quaternia/util/error.h"

namespace quaternia {

namespace {

// Larger sides are refused when reading, before any memory is allocated for them.
constexpr png_uint_32 kMaxReadSide = 1u << 16;
constexpr uint64_t kMaxReadPixels = uint64_t(1) << 28;
// The ancillary chunks libpng 1.6 knows, but tRNS (transparency), each with its terminating zero.
constexpr png_byte kIgnoredChunks[] =
    "bKGD\0cHRM\0eXIf\0gAMA\0hIST\0iCCP\0iTXt\0oFFs\0"
    "pCAL\0pHYs\0sBIT\0sCAL\0sPLT\0sRGB\0tEXt\0tIME\0zTXt";

struct ErrorState {
    char message[256] = "unknown libpng error";
};

[[noreturn]] void onPngError(png_structp png, png_const_charp message) {
    auto* state = static_cast<ErrorState*>(png_get_error_ptr(png));
    std::snprintf(state->message, sizeof state->message, "%s", message);
    png_longjmp(png, 1);
}

void onPngWarning(png_structp, png_const_charp) {}  // library code never prints

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
        // libpng reads an ancillary chunk into a buffer of its declared length, which it clears
        // first, before it finds that the file is shorter: a file of a hundred bytes that
        // declared a zTXt chunk of 1.6 GB took seconds, its default limit on chunk allocations
        // notwithstanding. No chunk but the image's own is used, so the others are skipped.
        png_set_keep_unknown_chunks(png_, PNG_HANDLE_CHUNK_NEVER, kIgnoredChunks,
                                    int(sizeof kIgnoredChunks / 5));
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

// The header of a file read as stored (PngRowReader): only the formats PngFormat names.
// Trivially destructible locals only.
bool readRawHeader(png_structp png, png_infop info, FILE* file, PngFormat* format) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_init_io(png, file);
    png_read_info(png, info);
    if (png_get_interlace_type(png, info) != PNG_INTERLACE_NONE)
        png_error(png, "interlaced PNGs are not read row by row");
    const int colorType = png_get_color_type(png, info), bitDepth = png_get_bit_depth(png, info);
    if (colorType != PNG_COLOR_TYPE_GRAY && colorType != PNG_COLOR_TYPE_RGB &&
        colorType != PNG_COLOR_TYPE_RGB_ALPHA)
        png_error(png, "only gray, RGB and RGBA PNGs are read row by row");
    if (bitDepth != 8 && bitDepth != 16)
        png_error(png, "only 8- and 16-bit PNGs are read row by row");
    format->width = int(png_get_image_width(png, info));
    format->height = int(png_get_image_height(png, info));
    format->bitDepth = bitDepth;
    format->colorType = PngColorType(colorType);
    png_start_read_image(png);
    return true;
}

// Trivially destructible locals only.
bool readRawRow(png_structp png, png_bytep row, bool last) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_row(png, row, nullptr);
    if (last) png_read_end(png, nullptr);
    return true;
}

}  // namespace

struct PngRowReader::State {
    using File = std::unique_ptr<FILE, int (*)(FILE*)>;
    ErrorState errors;  // before reader, whose libpng struct points to it
    File file;
    PngReader reader{&errors};
    std::string path;
    PngFormat format;
    size_t rowsRead = 0;

    State(File opened, const std::string& name) : file(std::move(opened)), path(name) {}
    std::runtime_error error(const char* reason) const {
        return std::runtime_error("cannot read PNG '" + path + "': " + reason);
    }
};

PngRowReader::PngRowReader(const std::string& path) {
    State::File file(std::fopen(path.c_str(), "rb"), std::fclose);
    if (!file) throw std::runtime_error("cannot open '" + path + "': " + errnoText(errno));
    state_ = std::make_unique<State>(std::move(file), path);
    if (!readRawHeader(state_->reader.png(), state_->reader.info(), state_->file.get(),
                       &state_->format))
        throw state_->error(state_->errors.message);
}

PngRowReader::~PngRowReader() = default;

const PngFormat& PngRowReader::format() const {
    return state_->format;
}

size_t PngRowReader::rowsRead() const {
    return state_->rowsRead;
}

void PngRowReader::readRow(std::span<uint8_t> row) {
    State& state = *state_;
    if (row.size() != pngRowBytes(state.format))
        throw state.error("a row read into room of the wrong size");
    if (state.rowsRead >= size_t(state.format.height)) throw state.error("read past the last row");
    const bool last = state.rowsRead + 1 == size_t(state.format.height);
    if (!readRawRow(state.reader.png(), row.data(), last)) throw state.error(state.errors.message);
    ++state.rowsRead;
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
