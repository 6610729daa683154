#include "quaternia/render/render_png.h"

#include "quaternia/image/png_io.h"
#include "quaternia/image/png_writer.h"

namespace quaternia {

RenderResult renderForPng(const Scene& scene, RenderOptions options) {
    // Opaque frames come as PNG pixels, quantised tile by tile (no float image at all).
    options.opaquePngPixels = true;
    return render(scene, options);
}

std::vector<uint8_t> encodeRenderPng(const RenderResult& result, int bitDepth) {
    return result.pngPixels.empty() ? encodePng(result.image, bitDepth)
                                    : writePngBytes(result.pngPixelsFormat, result.pngPixels);
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

uint64_t renderPngMemoryBytes(const Scene& scene, bool depth) {
    const uint64_t pixels = uint64_t(scene.render.width) * uint64_t(scene.render.height);
    PngFormat format{scene.render.width, scene.render.height, scene.render.bitDepth,
                     PngColorType::Rgba};
    uint64_t bytes;
    if (scene.render.alpha == AlphaMode::Opaque) {
        format.colorType = PngColorType::Rgb;
        bytes = pngRowBytes(format) * uint64_t(format.height);  // RenderResult::pngPixels
    } else {
        bytes = pixels * sizeof(Rgba);  // RenderResult::image
    }
    // The encoded pieces and the file they are gathered into exist together for a moment.
    bytes += 2 * pngBytesBound(format);
    if (depth) {
        const PngFormat gray{scene.render.width, scene.render.height, 16, PngColorType::Gray};
        bytes += pixels * sizeof(float) + 2 * pngBytesBound(gray);
    }
    return bytes;
}

}  // namespace quaternia
