#include "quaternia/image/image.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace quaternia {

namespace {

size_t checkedPixelCount(int width, int height) {
    if (width < 0 || height < 0)
        throw std::invalid_argument("image size must not be negative, got " +
                                    std::to_string(width) + "x" + std::to_string(height));
    return size_t(width) * size_t(height);
}

}  // namespace

Image::Image(int width, int height)
    : width_(width), height_(height), pixels_(checkedPixelCount(width, height)) {}

GrayImage::GrayImage(int width, int height)
    : width_(width), height_(height), pixels_(checkedPixelCount(width, height)) {}

Mask Mask::blank(int width, int height) {
    Mask mask;
    mask.inside.assign(checkedPixelCount(width, height), 0);
    mask.width = width;
    mask.height = height;
    return mask;
}

int64_t Mask::count() const {
    return std::count_if(inside.begin(), inside.end(), [](uint8_t v) { return v != 0; });
}

Mask maskFromAlpha(const Image& image, float threshold) {
    Mask mask = Mask::blank(image.width(), image.height());
    const Image::Pixels& pixels = image.pixels();
    for (size_t i = 0; i < pixels.size(); ++i)
        mask.inside[i] = pixels[i].a > threshold ? 1 : 0;
    return mask;
}

Mask maskFromImage(const Image& image) {
    Mask mask = Mask::blank(image.width(), image.height());
    const Image::Pixels& pixels = image.pixels();
    for (size_t i = 0; i < pixels.size(); ++i) {
        const Rgba& p = pixels[i];
        // Rec. 709 weights; on a gray image this is the gray value itself.
        float luminance = 0.2126f * p.r + 0.7152f * p.g + 0.0722f * p.b;
        mask.inside[i] = luminance > 0.5f ? 1 : 0;
    }
    return mask;
}

}  // namespace quaternia
