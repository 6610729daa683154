#include "quaternia/image/exr_writer.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfOutputFile.h>

#include <cstring>
#include <set>
#include <stdexcept>

namespace quaternia {
namespace {

// An in-memory OStream: the caller writes the bytes where it likes (an AtomicFile: a temporary
// renamed over the target), so a failed or interrupted render leaves no half-written file.
class MemoryStream : public Imf::OStream {
  public:
    MemoryStream() : Imf::OStream("memory") {}
    void write(const char c[], int n) override {
        const size_t end = position_ + size_t(n);
        if (end > bytes_.size()) bytes_.resize(end);
        std::memcpy(bytes_.data() + position_, c, size_t(n));
        position_ = end;
    }
    uint64_t tellp() override { return position_; }
    void seekp(uint64_t position) override { position_ = size_t(position); }
    std::vector<uint8_t>& bytes() { return bytes_; }

  private:
    std::vector<uint8_t> bytes_;
    size_t position_ = 0;
};

}  // namespace

std::vector<uint8_t> encodeExr(const ExrImage& image) {
    const size_t count = size_t(image.width) * size_t(image.height);
    if (image.width <= 0 || image.height <= 0)
        throw std::invalid_argument("encodeExr: empty image");
    Imf::Header header(image.width, image.height);
    header.compression() = Imf::ZIP_COMPRESSION;
    Imf::FrameBuffer frame;
    std::set<std::string> names;
    for (const ExrChannel& channel : image.channels) {
        if (!names.insert(channel.name).second)
            throw std::invalid_argument("encodeExr: two channels named " + channel.name);
        const bool integer = channel.values.empty();
        if ((integer ? channel.integers.size() : channel.values.size()) != count)
            throw std::invalid_argument("encodeExr: channel " + channel.name +
                                        " has the wrong size");
        const Imf::PixelType type = integer ? Imf::UINT : Imf::FLOAT;
        const size_t size = integer ? sizeof(uint32_t) : sizeof(float);
        char* base = integer
                         ? reinterpret_cast<char*>(const_cast<uint32_t*>(channel.integers.data()))
                         : reinterpret_cast<char*>(const_cast<float*>(channel.values.data()));
        header.channels().insert(channel.name, Imf::Channel(type));
        frame.insert(channel.name, Imf::Slice(type, base, size, size * size_t(image.width)));
    }
    MemoryStream stream;
    {
        Imf::OutputFile file(stream, header, 1);
        file.setFrameBuffer(frame);
        file.writePixels(image.height);
    }
    return std::move(stream.bytes());
}

}  // namespace quaternia
