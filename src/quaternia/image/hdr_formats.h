// What hdr_image.cpp, hdr_radiance.cpp and hdr_exr.cpp share; not part of the library's
// interface (see hdr_image.h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "quaternia/image/hdr_image.h"
#include "quaternia/util/memory_budget.h"

namespace quaternia::hdr {

// The file being decoded and whom to blame.
struct Source {
    const std::vector<uint8_t>& bytes;
    const std::string& path;
    const std::string& key;
    const MemoryBudget& budget;
};

// The largest width or height read.
constexpr int64_t kMaxSide = 65536;

// Throws UserError(key, "KEY: 'PATH'" + detail), with any control character of the message
// (a newline in the path or in a library's message) replaced by '?', so that it is one line.
// `detail` starts with its own separator: " is truncated", ": no such file".
[[noreturn]] void fail(const Source& source, const std::string& detail);
[[noreturn]] void failTruncated(const Source& source);

// At most `length` characters of `text`, control characters replaced by '?', for messages.
std::string excerpt(const std::string& text, size_t length = 60);

// A UserError unless width and height are 1..kMaxSide.
void checkSize(const Source& source, int64_t width, int64_t height);

// checkSize, then requireMemory for the pixels
// plus `workingBytes` (a decoder's own buffers), then allocates the zeroed pixels.
HdrImage allocatePixels(const Source& source, int64_t width, int64_t height, uint64_t workingBytes);

// NaN, infinities and negative values become 0.
void clampPixels(HdrImage& image);

HdrImage decodeRadiance(const Source& source);  // hdr_radiance.cpp
HdrImage decodeExr(const Source& source);       // hdr_exr.cpp

}  // namespace quaternia::hdr
