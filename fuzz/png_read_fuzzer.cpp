// PNG reading (png_io.h): decodePng on the bytes, and PngRowReader on the same bytes as a file.
// std::runtime_error is the documented rejection of malformed data. A decoded image must hold
// values in [0, 1]; where the row reader reads the file too (non-interlaced gray, RGB or RGBA
// of 8 or 16 bits), its samples must be the decoded colours.
#include <sys/mman.h>
#include <unistd.h>

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "fuzz/fuzz_check.h"
#include "quaternia/image/png_io.h"

using namespace quaternia;

namespace {

uint32_t bigEndian32(const uint8_t* p) {
    return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | p[3];
}

// The image size an IHDR at the file's start declares, or 0. decodePng allocates the samples
// before it reads them (up to 2^28 pixels, the documented limit): large sizes would only
// measure the allocator and trip libFuzzer's malloc limit, so they are left out here.
uint64_t declaredPixels(const uint8_t* data, size_t size) {
    if (size < 24 || std::string_view(reinterpret_cast<const char*>(data) + 12, 4) != "IHDR")
        return 0;
    return uint64_t(bigEndian32(data + 16)) * bigEndian32(data + 20);
}

// A path that reads back the bytes, without touching a disk.
std::string memoryFile(const uint8_t* data, size_t size) {
    static const int fd = memfd_create("png_read_fuzzer", 0);
    FUZZ_CHECK(fd >= 0);
    FUZZ_CHECK(ftruncate(fd, 0) == 0);
    FUZZ_CHECK(pwrite(fd, data, size, 0) == ssize_t(size));
    return "/proc/self/fd/" + std::to_string(fd);
}

void compareRows(const uint8_t* data, size_t size, const Image& image) {
    std::optional<PngRowReader> reader;
    try {
        reader.emplace(memoryFile(data, size));
    } catch (const std::runtime_error&) {
        return;  // a format it does not read (interlaced, palette, low bit depths)
    }
    const PngFormat format = reader->format();
    FUZZ_CHECK(format.width == image.width() && format.height == image.height());
    const int channels = pngChannels(format.colorType), bytes = format.bitDepth / 8;
    std::vector<uint8_t> row(pngRowBytes(format));
    for (int y = 0; y < format.height; ++y) {
        try {
            reader->readRow(row);
        } catch (const std::runtime_error&) {
            return;
        }
        for (int x = 0; x < format.width; ++x) {
            const Rgba& pixel = image.at(x, y);
            const float colour[4] = {pixel.r, pixel.g, pixel.b, pixel.a};
            for (int c = 0; c < channels; ++c) {
                const uint8_t* s = &row[size_t((x * channels + c) * bytes)];
                const unsigned sample = bytes == 2 ? unsigned(s[0]) << 8 | s[1] : s[0];
                const float expected = float(sample * (bytes == 2 ? 1u : 257u)) / 65535.0f;
                FUZZ_CHECK(colour[c] == expected);
                if (channels == 1) FUZZ_CHECK(pixel.g == expected && pixel.b == expected);
            }
        }
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (declaredPixels(data, size) > (uint64_t(1) << 20)) return 0;
    Image image;
    try {
        image = decodePng({data, size});
    } catch (const std::runtime_error&) {
        return 0;
    }
    FUZZ_CHECK(image.width() > 0 && image.height() > 0);
    for (const Rgba& p : image.pixels()) {
        for (float v : {p.r, p.g, p.b, p.a})
            FUZZ_CHECK(v >= 0 && v <= 1);
    }
    compareRows(data, size, image);
    return 0;
}
