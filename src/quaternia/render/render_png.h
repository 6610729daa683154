// A scene rendered to the bytes of its PNG: the one way `quaternia render` writes its image and
// `quaternia animate` each frame, so that a frame of a film is byte for byte the render of that
// frame's scene. The two steps are apart so that a film encodes frame n while it renders frame
// n + 1; renderPng is both in one.
#pragma once

#include <cstdint>
#include <vector>

#include "quaternia/render/render.h"
#include "quaternia/scene/scene.h"

namespace quaternia {

// render() for a PNG: an opaque scene comes as PNG pixels (RenderOptions::opaquePngPixels), any
// other as the float image. Throws UserError for a bad scene before any work.
RenderResult renderForPng(const Scene& scene, RenderOptions options);

// The PNG of a completed renderForPng result, at the scene's render.bit_depth.
std::vector<uint8_t> encodeRenderPng(const RenderResult& result, int bitDepth);

struct PngRender {
    std::vector<uint8_t> png;
    std::vector<uint8_t> depthPng;  // 16-bit grey, where options.depth asked for it
    RenderStats stats;
    bool completed = true;  // false if cancelled; the bytes are then empty
};

// renderForPng, then encodeRenderPng (and the depth pass when options.depth).
PngRender renderPng(const Scene& scene, const RenderOptions& options);

// An upper bound of the memory renderPng(scene) takes beyond a small fixed amount: the buffers
// that grow with the image (the float image or the PNG pixels, the depth pass, the encoded
// files while they are assembled); per-thread scratch is a tile's and not counted.
uint64_t renderPngMemoryBytes(const Scene& scene, bool depth);

}  // namespace quaternia
