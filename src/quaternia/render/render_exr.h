// A scene rendered to OpenEXR with its passes, for compositing (`quaternia render -o out.exr`):
// the linear colour with premultiplied alpha, as EXR expects, and the passes of RenderPasses.
#pragma once

#include <cstdint>
#include <vector>

#include "quaternia/render/pixel_certificate.h"
#include "quaternia/render/render.h"
#include "quaternia/scene/scene.h"

namespace quaternia {

// The channels written, in the order OpenEXR stores them (by name): A, B, G, N.X, N.Y, N.Z, R
// (linear colour times alpha), Z (distance from the camera along the ray,
// RenderPasses::kNoHitDistance where nothing was hit), id (unsigned: 1 the set, 0 nothing) and
// trap (the orbit trap min |z_n|).
// With a certificate (pixel_certificate.h) of the same size, also certified.class (unsigned:
// 0 missed, 128 undecided, 255 hit), certified.near and certified.far (the depth interval of
// certain hits, PixelCertificate::kNoDepth elsewhere).
std::vector<uint8_t> encodeRenderExr(const RenderPasses& passes,
                                     const PixelCertificate* certificate = nullptr);

// An upper bound of the memory a render to EXR takes beyond a small fixed amount: the float
// image, the passes, their channels and the encoded file.
uint64_t renderExrMemoryBytes(const Scene& scene);

}  // namespace quaternia
