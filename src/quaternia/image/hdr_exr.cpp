// OpenEXR files (hdr_image.h), read through the OpenEXR 3.1 library from memory. Before the
// library sees the file, its headers are walked here ("OpenEXR File Layout": magic, version
// and flags, then attributes name\0 type\0 size value, an empty name closing each header) for
// the data window, tiles, compression and channels, so that a side over 65536, and the pixels'
// and the library's buffers, are refused (requireMemory) before the library allocates them. The
// library throws Iex exceptions (std::exception) for a corrupt file; they become UserErrors.
#include <Iex.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "quaternia/image/hdr_formats.h"
#include "quaternia/util/error.h"

namespace quaternia::hdr {

namespace {

// Version field flags (a tiled file is told by its tiles attribute, which is what is read).
constexpr uint32_t kLongNamesFlag = 0x400, kDeepFlag = 0x800, kMultiPartFlag = 0x1000;

// Scanlines that one chunk holds, by the compression attribute's value (NO, RLE, ZIPS, ZIP,
// PIZ, PXR24, B44, B44A, DWAA, DWAB).
constexpr int kLinesPerChunk[] = {1, 1, 1, 16, 32, 16, 32, 32, 32, 256};

// An in-memory IStream; a read past the end is remembered, so that the error says "truncated".
class MemoryIStream : public Imf::IStream {
  public:
    MemoryIStream(const std::vector<uint8_t>& bytes, const std::string& name)
        : Imf::IStream(name.c_str()), bytes_(bytes) {}
    bool read(char c[], int n) override {
        if (n < 0 || position_ > bytes_.size() || size_t(n) > bytes_.size() - position_) {
            pastEnd_ = true;
            throw Iex::InputExc("unexpected end of file");
        }
        std::memcpy(c, bytes_.data() + position_, size_t(n));
        position_ += size_t(n);
        return position_ < bytes_.size();
    }
    uint64_t tellg() override { return position_; }
    void seekg(uint64_t position) override { position_ = position; }
    bool pastEnd() const { return pastEnd_; }

  private:
    const std::vector<uint8_t>& bytes_;
    uint64_t position_ = 0;
    bool pastEnd_ = false;
};

// What the headers say, for the first part and for the buffers of any part.
struct Layout {
    int64_t width = 0, height = 0;  // the first part's data window
    double workingBytes = 0;        // the library's buffers for the largest part
};

class HeaderWalker {
  public:
    explicit HeaderWalker(const Source& source) : source_(source) {}

    Layout walk() {
        take(4);  // the magic number, checked by the caller
        const uint32_t version = readU32();
        if (version & kDeepFlag) fail(source_, " holds deep data, which is not read");
        const size_t maxName = version & kLongNamesFlag ? 256 : 32;
        Layout layout;
        walkHeader(maxName, layout, true);
        // A multi-part file's headers follow one another up to an empty one.
        while (version & kMultiPartFlag) {
            if (position_ < source_.bytes.size() && source_.bytes[position_] == 0) break;
            walkHeader(maxName, layout, false);
        }
        return layout;
    }

  private:
    const uint8_t* take(size_t n) {
        if (n > source_.bytes.size() - position_) failTruncated(source_);
        const uint8_t* at = source_.bytes.data() + position_;
        position_ += n;
        return at;
    }
    uint32_t readU32() {  // little-endian
        const uint8_t* p = take(4);
        return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
    }
    std::string readName(size_t maxName) {
        const uint8_t* begin = source_.bytes.data() + position_;
        const size_t left = source_.bytes.size() - position_;
        const void* end = std::memchr(begin, 0, std::min(left, maxName));
        if (!end && left < maxName) failTruncated(source_);
        if (!end) corrupt("a name longer than " + std::to_string(maxName - 1) + " characters");
        const size_t length = size_t(static_cast<const uint8_t*>(end) - begin);
        return std::string(reinterpret_cast<const char*>(take(length + 1)), length);
    }
    [[noreturn]] void corrupt(const std::string& reason) const {
        fail(source_, " is not a valid OpenEXR file (" + reason + ")");
    }

    void walkHeader(size_t maxName, Layout& layout, bool first) {
        int64_t window[4] = {0, 0, -1, -1};
        bool haveWindow = false;
        int64_t tileWidth = 0, tileHeight = 0;
        int compression = 0;
        double channels = 0;
        for (std::string name; !(name = readName(maxName)).empty();) {
            const std::string type = readName(maxName);
            const uint32_t size = readU32();
            if (size > std::numeric_limits<int32_t>::max()) corrupt("a negative attribute size");
            const size_t start = position_;
            const uint8_t* value = take(size);
            if (name == "dataWindow" && type == "box2i" && size == 16) {
                position_ = start;
                for (int64_t& v : window)
                    v = int32_t(readU32());
                haveWindow = true;
            } else if (name == "tiles" && type == "tiledesc" && size == 9) {
                position_ = start;
                tileWidth = readU32();
                tileHeight = readU32();
            } else if (name == "compression" && type == "compression" && size == 1) {
                compression = value[0];
            } else if (name == "channels" && type == "chlist") {
                // name\0, then 16 bytes (type, pLinear, reserved, xSampling, ySampling) each.
                for (size_t at = 0; at < size && value[at] != 0; ++channels) {
                    const void* end = std::memchr(value + at, 0, size - at);
                    if (!end) break;
                    at = size_t(static_cast<const uint8_t*>(end) - value) + 1 + 16;
                }
            }
            position_ = start + size;
        }
        if (!haveWindow) corrupt("no dataWindow attribute");
        const int64_t width = window[2] - window[0] + 1, height = window[3] - window[1] + 1;
        checkSize(source_, width, height);
        if (tileWidth < 0 || tileHeight < 0 || tileWidth > kMaxSide || tileHeight > kMaxSide)
            corrupt("tiles of " + std::to_string(tileWidth) + " x " + std::to_string(tileHeight));
        // Rows of the image that one chunk covers, and the buffers for it: compressed and
        // uncompressed, every channel at 4 bytes a sample at most, plus a tile when tiled; and
        // the table of chunk offsets, 8 bytes a chunk (at most 4 times the tiles of the full
        // level, with the levels of a mipmap or ripmap).
        const bool tiled = tileWidth > 0 || tileHeight > 0;
        const int64_t rows = tiled ? std::min(std::max<int64_t>(tileHeight, 1), height)
                                   : kLinesPerChunk[std::min(compression, 9)];
        const double tile = double(tileWidth) * double(tileHeight);
        const double chunks =
            tiled ? 4 * std::ceil(double(width) / double(std::max<int64_t>(tileWidth, 1))) *
                        std::ceil(double(height) / double(rows))
                  : std::ceil(double(height) / double(rows));
        const double bytes = 2 * 4 * channels * (double(width) * double(rows) + tile) + 8 * chunks;
        layout.workingBytes = std::max(layout.workingBytes, bytes);
        if (first) {
            layout.width = width;
            layout.height = height;
        }
    }

    const Source& source_;
    size_t position_ = 0;
};

}  // namespace

HdrImage decodeExr(const Source& source) {
    const Layout layout = HeaderWalker(source).walk();
    const uint64_t working =
        uint64_t(std::min(layout.workingBytes, double(uint64_t(1) << 62)));  // saturated
    HdrImage image = allocatePixels(source, layout.width, layout.height, working);
    MemoryIStream stream(source.bytes, source.path);
    bool rgb = true;  // else Y, read into R
    try {
        // No threads: one line buffer, as estimated above.
        Imf::InputFile file(stream, 0);
        const Imath::Box2i window = file.header().dataWindow();
        if (int64_t(window.max.x) - window.min.x + 1 != layout.width ||
            int64_t(window.max.y) - window.min.y + 1 != layout.height)
            fail(source, " is not a valid OpenEXR file (its headers disagree)");
        const Imf::ChannelList& channels = file.header().channels();
        rgb = channels.findChannel("R") && channels.findChannel("G") && channels.findChannel("B");
        if (!rgb && channels.findChannel("Y") &&
            (channels.findChannel("RY") || channels.findChannel("BY")))
            fail(source, " is a luminance/chroma (Y, RY, BY) OpenEXR file, which is not read");
        if (!rgb && !channels.findChannel("Y")) {
            std::string names;
            for (auto it = channels.begin(); it != channels.end(); ++it)
                names += std::string(names.empty() ? "" : ", ") + it.name();
            fail(source, " has no R, G, B or Y channels (it has " +
                             (names.empty() ? std::string("none") : excerpt(names)) + ")");
        }
        Imf::FrameBuffer frame;
        const char* names[] = {"R", "G", "B"};
        for (int channel = 0; channel < (rgb ? 3 : 1); ++channel) {
            const char* name = rgb ? names[channel] : "Y";
            if (channels.findChannel(name)->type == Imf::UINT)
                fail(source, std::string(" has an integer ") + name +
                                 " channel; only half or float colours are read");
            frame.insert(
                name, Imf::Slice::Make(Imf::FLOAT, image.rgb.data() + channel, window,
                                       3 * sizeof(float), 3 * sizeof(float) * size_t(image.width)));
        }
        file.setFrameBuffer(frame);
        file.readPixels(window.min.y, window.max.y);
    } catch (const UserError&) {
        throw;
    } catch (const std::exception& error) {
        if (stream.pastEnd()) failTruncated(source);
        fail(source, " is not a valid OpenEXR file (" + excerpt(error.what(), 200) + ")");
    }
    if (!rgb) {  // grey: Y was read into R
        for (size_t i = 0; i < image.rgb.size(); i += 3)
            image.rgb[i + 1] = image.rgb[i + 2] = image.rgb[i];
    }
    clampPixels(image);
    return image;
}

}  // namespace quaternia::hdr
