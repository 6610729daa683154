// Reading the file and choosing the decoder (hdr_image.h); the formats are hdr_radiance.cpp's
// and hdr_exr.cpp's.
#include "quaternia/image/hdr_image.h"

#include <sys/stat.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <system_error>

#include "quaternia/image/hdr_formats.h"
#include "quaternia/util/error.h"

namespace quaternia {

namespace hdr {

namespace {

std::string printable(std::string text) {
    for (char& c : text)
        if ((unsigned char)c < 0x20 || c == 0x7f) c = '?';
    return text;
}

std::string what(const Source& source) {
    return source.key + ": the map '" + source.path + "'";
}

constexpr const char* kAdvice = "use a smaller map or raise --memory-budget";

}  // namespace

void fail(const Source& source, const std::string& detail) {
    throw UserError(source.key, printable(source.key + ": '" + source.path + "'" + detail));
}

void failTruncated(const Source& source) {
    fail(source, " is truncated");
}

std::string excerpt(const std::string& text, size_t length) {
    return printable(text.size() > length ? text.substr(0, length - 3) + "..." : text);
}

void checkSize(const Source& source, int64_t width, int64_t height) {
    if (width <= 0 || height <= 0 || width > kMaxSide || height > kMaxSide)
        fail(source, " is " + std::to_string(width) + " x " + std::to_string(height) +
                         " pixels; the sides must be 1 to " + std::to_string(kMaxSide));
}

HdrImage allocatePixels(const Source& source, int64_t width, int64_t height,
                        uint64_t workingBytes) {
    checkSize(source, width, height);
    const uint64_t count = uint64_t(width) * uint64_t(height) * 3;
    requireMemory(count * sizeof(float) + workingBytes, source.budget, source.key, what(source),
                  kAdvice);
    HdrImage image;
    image.width = int(width);
    image.height = int(height);
    image.rgb.assign(count, 0.0f);
    return image;
}

void clampPixels(HdrImage& image) {
    for (float& v : image.rgb)
        if (!(v >= 0 && v <= std::numeric_limits<float>::max())) v = 0;
}

}  // namespace hdr

namespace {

bool startsWith(const std::vector<uint8_t>& bytes, const std::string& magic) {
    return bytes.size() >= magic.size() &&
           std::memcmp(bytes.data(), magic.data(), magic.size()) == 0;
}

// True when `bytes` is a proper prefix of `magic`: the file ends before it could be told apart.
bool prefixOf(const std::vector<uint8_t>& bytes, const std::string& magic) {
    return bytes.size() < magic.size() &&
           std::memcmp(bytes.data(), magic.data(), bytes.size()) == 0;
}

std::string reasonOf(int error) {
    if (error == EACCES || error == EPERM) return "permission denied";
    std::string text = std::generic_category().message(error);
    if (!text.empty()) text[0] = char(std::tolower((unsigned char)text[0]));
    return text;
}

}  // namespace

HdrImage decodeHdrImage(const std::vector<uint8_t>& bytes, const std::string& path,
                        const std::string& key, const MemoryBudget& budget) {
    const hdr::Source source{bytes, path, key, budget};
    const std::string exr("\x76\x2f\x31\x01", 4), radiance = "#?RADIANCE", rgbe = "#?RGBE";
    if (startsWith(bytes, exr)) return hdr::decodeExr(source);
    if (startsWith(bytes, radiance) || startsWith(bytes, rgbe)) return hdr::decodeRadiance(source);
    if (bytes.empty()) hdr::fail(source, " is empty, not an HDR image (Radiance .hdr or OpenEXR)");
    if (prefixOf(bytes, exr) || prefixOf(bytes, radiance) || prefixOf(bytes, rgbe))
        hdr::failTruncated(source);
    hdr::fail(source, " is not an HDR image (Radiance .hdr or OpenEXR)");
}

HdrImage readHdrImage(const std::string& path, const std::string& key, const MemoryBudget& budget) {
    const std::vector<uint8_t> none;
    const hdr::Source source{none, path, key, budget};
    std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "rb"), std::fclose);
    if (!file) {
        const int error = errno;
        if (error == ENOENT || error == ENOTDIR) hdr::fail(source, ": no such file");
        hdr::fail(source, ": cannot read (" + reasonOf(error) + ")");
    }
    // The file's bytes count against the budget too: checked before reading (the size that
    // stat reports) and as they come (a file that grows, or one that stat cannot size).
    struct stat status;
    if (::fstat(fileno(file.get()), &status) == 0 && S_ISREG(status.st_mode))
        requireMemory(uint64_t(status.st_size), budget, key, hdr::what(source), hdr::kAdvice);
    std::vector<uint8_t> bytes;
    uint8_t buffer[1 << 16];
    size_t got;
    while ((got = std::fread(buffer, 1, sizeof buffer, file.get())) > 0) {
        requireMemory(bytes.size() + got, budget, key, hdr::what(source), hdr::kAdvice);
        bytes.insert(bytes.end(), buffer, buffer + got);
    }
    if (std::ferror(file.get())) hdr::fail(source, ": cannot read (" + reasonOf(errno) + ")");
    file.reset();
    return decodeHdrImage(bytes, path, key, budget);
}

}  // namespace quaternia
