// OpenEXR output (Debian libopenexr-dev): scanline images of named channels, ZIP-compressed, as
// compositors (Blender, Nuke, Natron) read them. Channels are 32-bit floats or unsigned
// integers; OpenEXR stores them in the order of their names, whatever the order given here.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace quaternia {

struct ExrChannel {
    std::string name;                // e.g. "R", "Z", "N.X" (layer "N"), "trap"
    std::vector<float> values;       // width x height, row-major; or
    std::vector<uint32_t> integers;  // for an integer channel (values empty)
};

struct ExrImage {
    int width = 0, height = 0;
    std::vector<ExrChannel> channels;
};

// The file's bytes. Throws std::invalid_argument when a channel's size is not width x height
// or two channels share a name.
std::vector<uint8_t> encodeExr(const ExrImage& image);

}  // namespace quaternia
