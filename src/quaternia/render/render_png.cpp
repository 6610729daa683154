#include "quaternia/render/render_png.h"

#include "quaternia/image/png_io.h"
#include "quaternia/image/png_writer.h"

namespace quaternia {

RenderResult renderForPng(const Scene& scene, RenderOptions options) {
    // Opaque frames come as PNG samples, quantised tile by tile (no float image at all).
    options.opaqueSamples = true;
    return render(scene, options);
}

std::vector<uint8_t> encodeRenderPng(const RenderResult& result, int bitDepth) {
    return result.samples.empty() ? encodePng(result.image, bitDepth)
                                  : writePngBytes(result.samplesFormat, result.samples);
}

PngRender renderPng(const Scene& scene, const RenderOptions& options) {
    RenderResult result = renderForPng(scene, options);
    PngRender out;
    out.stats = result.stats;
    out.completed = result.completed;
    if (!result.completed) return out;
    out.png = encodeRenderPng(result, scene.render.bitDepth);
    if (options.depth) out.depthPng = encodeGrayPng16(result.depth);
    return out;
}

}  // namespace quaternia
