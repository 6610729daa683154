// Radiance RGBE files (hdr_image.h): Ward, "Real Pixels", Graphics Gems II, and "Radiance File
// Formats". Every read is bounded by the bytes left and every run by the scanline's width, so a
// truncated or malicious file ends in a UserError, never past the buffer or in a long loop.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "quaternia/image/hdr_formats.h"
#include "quaternia/image/hdr_image.h"

namespace quaternia {

namespace {

// The scanline marker holds the width in 15 bits; Ward's writer uses runs from width 8 on.
constexpr int kMinRleWidth = 8, kMaxRleWidth = 0x7fff;
constexpr int kMinRun = 4;  // shorter runs cost more than literals (Ward's MINRUN)

class Reader {
  public:
    explicit Reader(const hdr::Source& source) : source_(source) {}

    size_t left() const { return source_.bytes.size() - position_; }
    const uint8_t* take(size_t n) {  // n bytes, or a UserError when fewer are left
        if (n > left()) hdr::failTruncated(source_);
        const uint8_t* at = source_.bytes.data() + position_;
        position_ += n;
        return at;
    }
    const uint8_t* peek() const { return source_.bytes.data() + position_; }

    // The next line without its '\n' (and a '\r' before it).
    std::string line() {
        const uint8_t* begin = peek();
        const void* end = std::memchr(begin, '\n', left());
        if (!end) hdr::failTruncated(source_);
        const size_t length = size_t(static_cast<const uint8_t*>(end) - begin);
        std::string text(reinterpret_cast<const char*>(take(length + 1)), length);
        if (!text.empty() && text.back() == '\r') text.pop_back();
        return text;
    }

    [[noreturn]] void corrupt(const std::string& reason) const {
        hdr::fail(source_, " is not a valid Radiance .hdr file (" + reason + ")");
    }

  private:
    const hdr::Source& source_;
    size_t position_ = 0;
};

bool parseNumber(std::string_view text, double& value) {
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    return error == std::errc() && end == text.data() + text.size();
}

bool parseSide(std::string_view text, int64_t& value) {
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    return error == std::errc() && end == text.data() + text.size();
}

// "-Y H +X W": four words separated by single spaces.
bool parseResolution(const std::string& line, int64_t& width, int64_t& height) {
    std::vector<std::string_view> words;
    std::string_view rest(line);
    for (size_t space; (space = rest.find(' ')) != std::string_view::npos;) {
        words.push_back(rest.substr(0, space));
        rest.remove_prefix(space + 1);
    }
    words.push_back(rest);
    return words.size() == 4 && words[0] == "-Y" && words[2] == "+X" &&
           parseSide(words[1], height) && parseSide(words[3], width);
}

// One scanline of `width` RGBE pixels into `scan`.
void readScanline(Reader& in, int width, uint8_t* scan) {
    const uint8_t* head = in.left() >= 4 ? in.peek() : nullptr;
    if (width >= kMinRleWidth && width <= kMaxRleWidth && head && head[0] == 2 && head[1] == 2 &&
        !(head[2] & 0x80)) {
        in.take(4);
        if (((head[2] << 8) | head[3]) != width)
            in.corrupt("a scanline of " + std::to_string((head[2] << 8) | head[3]) +
                       " pixels in an image " + std::to_string(width) + " wide");
        for (int channel = 0; channel < 4; ++channel) {
            for (int x = 0; x < width;) {
                const int code = *in.take(1);
                const int count = code > 128 ? code - 128 : code;
                if (count == 0 || count > width - x) in.corrupt("a run past the scanline's end");
                if (code > 128) {
                    const uint8_t value = *in.take(1);
                    for (int i = 0; i < count; ++i)
                        scan[4 * (x + i) + channel] = value;
                } else {
                    const uint8_t* values = in.take(size_t(count));
                    for (int i = 0; i < count; ++i)
                        scan[4 * (x + i) + channel] = values[i];
                }
                x += count;
            }
        }
        return;
    }
    // Flat, with Ward's old-style runs: 1, 1, 1, n repeats the previous pixel n << shift times,
    // the shift growing by 8 with each such pixel in a row.
    int shift = 0;
    for (int x = 0; x < width;) {
        const uint8_t* pixel = in.take(4);
        if (pixel[0] == 1 && pixel[1] == 1 && pixel[2] == 1) {
            if (x == 0 || shift > 16) in.corrupt("a run without a pixel to repeat");
            const int64_t count = int64_t(pixel[3]) << shift;
            if (count > width - x) in.corrupt("a run past the scanline's end");
            for (int64_t i = 0; i < count; ++i, ++x)
                std::memcpy(scan + 4 * x, scan + 4 * (x - 1), 4);
            shift += 8;
        } else {
            std::memcpy(scan + 4 * x, pixel, 4);
            ++x;
            shift = 0;
        }
    }
}

// Ward's float2rgbe with exact arithmetic: frexp gives v = m * 2^e, m in [0.5, 1); the mantissa
// bytes are floor(c * 2^(8 - e)) (multiplying by a power of two is exact in double), so the
// largest channel's byte is floor(m * 256), 128..255.
void toRgbe(const float* rgb, uint8_t* out) {
    double c[3];
    for (int i = 0; i < 3; ++i)
        c[i] = std::isfinite(rgb[i]) && rgb[i] > 0 ? double(rgb[i]) : 0.0;
    const double largest = std::max(c[0], std::max(c[1], c[2]));
    int exponent = 0;
    std::frexp(largest, &exponent);
    if (largest == 0 || exponent + 128 < 1) {
        std::memset(out, 0, 4);
        return;
    }
    exponent = std::min(exponent, 127);  // 2^127 and above saturate at 255 * 2^(127 - 8)
    for (int i = 0; i < 3; ++i)
        out[i] = uint8_t(std::min(255.0, std::floor(std::ldexp(c[i], 8 - exponent))));
    out[3] = uint8_t(exponent + 128);
}

// A run-length encoded component (Ward's fwritecolrs): runs of kMinRun or more equal bytes,
// at most 127 each, as 128 + count, value; the bytes between as literals of at most 128.
void writeComponent(const uint8_t* scan, int channel, int width, std::vector<uint8_t>& out) {
    const auto at = [&](int x) { return scan[4 * x + channel]; };
    for (int x = 0; x < width;) {
        int begin = x, run = 0;
        while (begin < width) {
            run = 1;
            while (begin + run < width && run < 127 && at(begin + run) == at(begin))
                ++run;
            if (run >= kMinRun) break;
            begin += run;
            run = 0;
        }
        begin = std::min(begin, width);
        while (x < begin) {
            const int count = std::min(128, begin - x);
            out.push_back(uint8_t(count));
            for (int i = 0; i < count; ++i)
                out.push_back(at(x + i));
            x += count;
        }
        if (run >= kMinRun) {
            out.push_back(uint8_t(128 + run));
            out.push_back(at(begin));
            x = begin + run;
        }
    }
}

}  // namespace

namespace hdr {

HdrImage decodeRadiance(const Source& source) {
    Reader in(source);
    in.line();  // "#?RADIANCE" or "#?RGBE", checked by the caller
    double exposure = 1;
    for (std::string line; !(line = in.line()).empty();) {
        if (line.rfind("FORMAT=", 0) == 0) {
            if (line != "FORMAT=32-bit_rle_rgbe")
                in.corrupt("'" + excerpt(line) + "'; only FORMAT=32-bit_rle_rgbe is read");
        } else if (line.rfind("EXPOSURE=", 0) == 0) {
            std::string_view text(line);
            text.remove_prefix(9);
            while (!text.empty() && (text.front() == ' ' || text.front() == '\t'))
                text.remove_prefix(1);
            while (!text.empty() && (text.back() == ' ' || text.back() == '\t'))
                text.remove_suffix(1);
            double value;
            if (!parseNumber(text, value) || !std::isfinite(value) || value <= 0)
                in.corrupt("'" + excerpt(line) + "'; an exposure must be a positive number");
            exposure *= value;
        }
    }
    const std::string resolution = in.line();
    int64_t width = 0, height = 0;
    if (!parseResolution(resolution, width, height))
        in.corrupt("resolution line '" + excerpt(resolution) + "'; only '-Y H +X W' is read");
    // Every scanline takes 4 bytes at least: a file too short for them all is truncated,
    // found before the pixels are allocated.
    checkSize(source, width, height);
    if (uint64_t(height) * 4 > in.left()) failTruncated(source);
    HdrImage image = allocatePixels(source, width, height, uint64_t(width) * 4);
    std::vector<uint8_t> scan(size_t(width) * 4);
    const double scale = 1 / exposure;
    float* out = image.rgb.data();
    for (int y = 0; y < image.height; ++y) {
        readScanline(in, image.width, scan.data());
        for (int x = 0; x < image.width; ++x, out += 3) {
            const uint8_t* pixel = &scan[4 * size_t(x)];
            if (pixel[3] == 0) continue;  // zero, as allocated
            const double unit = std::ldexp(scale, int(pixel[3]) - (128 + 8));
            for (int i = 0; i < 3; ++i)
                out[i] = float((pixel[i] + 0.5) * unit);
        }
    }
    clampPixels(image);
    return image;
}

}  // namespace hdr

std::vector<uint8_t> encodeRadianceHdr(const HdrImage& image) {
    if (image.width <= 0 || image.height <= 0)
        throw std::invalid_argument("encodeRadianceHdr: empty image");
    if (image.rgb.size() != size_t(image.width) * size_t(image.height) * 3)
        throw std::invalid_argument("encodeRadianceHdr: rgb is not 3 x width x height floats");
    const std::string header = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " +
                               std::to_string(image.height) + " +X " + std::to_string(image.width) +
                               "\n";
    std::vector<uint8_t> out(header.begin(), header.end());
    const int width = image.width;
    const bool rle = width >= kMinRleWidth && width <= kMaxRleWidth;
    std::vector<uint8_t> scan(size_t(width) * 4);
    for (int y = 0; y < image.height; ++y) {
        const float* row = image.rgb.data() + size_t(y) * size_t(width) * 3;
        for (int x = 0; x < width; ++x)
            toRgbe(row + 3 * size_t(x), &scan[4 * size_t(x)]);
        if (!rle) {
            out.insert(out.end(), scan.begin(), scan.end());
            continue;
        }
        out.insert(out.end(), {2, 2, uint8_t(width >> 8), uint8_t(width & 0xff)});
        for (int channel = 0; channel < 4; ++channel)
            writeComponent(scan.data(), channel, width, out);
    }
    return out;
}

}  // namespace quaternia
