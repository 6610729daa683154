#include "mask_tool.h"

#include <cstdio>
#include <stdexcept>

namespace quaternia::bench {

MaskSource parseMaskSource(const std::string& name) {
    if (name == "alpha") return MaskSource::Alpha;
    if (name == "luma") return MaskSource::Luma;
    throw std::invalid_argument("mask source '" + name + "' is neither 'alpha' nor 'luma'");
}

Mask maskOf(const Image& image, MaskSource source) {
    return source == MaskSource::Alpha ? maskFromAlpha(image) : maskFromImage(image);
}

std::string comparisonJson(const MaskComparison& c) {
    char text[300];
    std::snprintf(text, sizeof text,
                  "{\"iou\": %.6f, \"count_a\": %lld, \"count_b\": %lld, \"intersection\": %lld, "
                  "\"union\": %lld, \"far_from_b\": %lld, \"far_from_a\": %lld}",
                  c.iou, static_cast<long long>(c.countA), static_cast<long long>(c.countB),
                  static_cast<long long>(c.intersection), static_cast<long long>(c.unionCount),
                  static_cast<long long>(c.farFromB), static_cast<long long>(c.farFromA));
    return text;
}

}  // namespace quaternia::bench
