// The silhouette comparison of bench/compare: a mask taken from any renderer's PNG (by alpha
// or by luminance) against the brute-force reference mask, with mask_compare's measures, as one
// line of JSON that the script reads.
#pragma once

#include <string>

#include "quaternia/image/image.h"
#include "quaternia/image/mask_compare.h"

namespace quaternia::bench {

// How a PNG becomes a mask: "alpha" (coverage above one half: Quaternia with
// render.alpha = "coverage", Mandelbulber2's png16alpha) or "luma" (luminance above one half:
// white object on black, as POV-Ray's mask scenes and the brute-force masks).
enum class MaskSource { Alpha, Luma };

// "alpha" or "luma"; throws std::invalid_argument for anything else.
MaskSource parseMaskSource(const std::string& name);

Mask maskOf(const Image& image, MaskSource source);

// {"iou": 0.994712, "count_a": ..., "count_b": ..., "intersection": ..., "union": ...,
//  "far_from_b": ..., "far_from_a": ...}: A is the tested render, B the reference.
std::string comparisonJson(const MaskComparison& comparison);

}  // namespace quaternia::bench
