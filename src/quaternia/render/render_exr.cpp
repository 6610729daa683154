#include "quaternia/render/render_exr.h"

#include "quaternia/image/exr_writer.h"

namespace quaternia {

std::vector<uint8_t> encodeRenderExr(const RenderPasses& passes,
                                     const PixelCertificate* certificate) {
    const size_t count = size_t(passes.width) * size_t(passes.height);
    ExrImage image;
    image.width = passes.width;
    image.height = passes.height;
    auto channel = [&](const char* name) -> std::vector<float>& {
        image.channels.push_back(ExrChannel{name, std::vector<float>(count), {}});
        return image.channels.back().values;
    };
    // EXR's colour is premultiplied by alpha (OpenEXR, "Technical Introduction").
    for (int c = 0; c < 4; ++c) {
        std::vector<float>& values = channel(c == 0 ? "R" : c == 1 ? "G" : c == 2 ? "B" : "A");
        for (size_t i = 0; i < count; ++i) {
            const Rgba& p = passes.linear[i];
            values[i] = c == 3 ? p.a : (c == 0 ? p.r : c == 1 ? p.g : p.b) * p.a;
        }
    }
    channel("Z") = passes.distance;
    for (int axis = 0; axis < 3; ++axis) {
        std::vector<float>& values = channel(axis == 0 ? "N.X" : axis == 1 ? "N.Y" : "N.Z");
        for (size_t i = 0; i < count; ++i)
            values[i] = passes.normal[i][size_t(axis)];
    }
    channel("trap") = passes.trap;
    image.channels.push_back(ExrChannel{"id", {}, passes.object});
    if (certificate) {
        image.channels.push_back(ExrChannel{
            "certified.class",
            {},
            std::vector<uint32_t>(certificate->classes.begin(), certificate->classes.end())});
        channel("certified.near") = certificate->nearestHit;
        channel("certified.far") = certificate->farthestHit;
    }
    return encodeExr(image);
}

uint64_t renderExrMemoryBytes(const Scene& scene) {
    const uint64_t pixels = uint64_t(scene.render.width) * uint64_t(scene.render.height);
    // RenderResult::image (16) and the passes (16 + 4 + 4 + 12 + 4), the ten channels (40), and
    // the file, ZIP-compressed but bounded by the raw channels (40) plus its tables.
    return pixels * (16 + 40 + 40 + 40) + (64u << 10);
}

}  // namespace quaternia
