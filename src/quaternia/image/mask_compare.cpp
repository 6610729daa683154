#include "quaternia/image/mask_compare.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace quaternia {

namespace {

void checkShape(const Mask& mask, const char* name) {
    if (mask.width < 0 || mask.height < 0 ||
        mask.inside.size() != size_t(mask.width) * size_t(mask.height))
        throw std::invalid_argument(std::string("mask ") + name + " holds " +
                                    std::to_string(mask.inside.size()) + " values for " +
                                    std::to_string(mask.width) + "x" + std::to_string(mask.height) +
                                    " pixels");
}

void checkSameSize(const Mask& a, const Mask& b) {
    checkShape(a, "A");
    checkShape(b, "B");
    if (a.width != b.width || a.height != b.height)
        throw std::invalid_argument(
            "cannot compare a " + std::to_string(a.width) + "x" + std::to_string(a.height) +
            " mask with a " + std::to_string(b.width) + "x" + std::to_string(b.height) + " one");
}

// Whether `mask` has an inside pixel in the 3 x 3 neighbourhood of (x, y): (x, y) lies in the
// mask dilated by one pixel in all 8 directions.
bool nearInside(const Mask& mask, int x, int y) {
    const int xLo = std::max(x - 1, 0), xHi = std::min(x + 1, mask.width - 1);
    const int yLo = std::max(y - 1, 0), yHi = std::min(y + 1, mask.height - 1);
    for (int ny = yLo; ny <= yHi; ++ny) {
        for (int nx = xLo; nx <= xHi; ++nx) {
            if (mask.at(nx, ny)) return true;
        }
    }
    return false;
}

}  // namespace

MaskComparison compareMasks(const Mask& a, const Mask& b) {
    checkSameSize(a, b);
    MaskComparison c;
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            const bool inA = a.at(x, y), inB = b.at(x, y);
            c.countA += inA;
            c.countB += inB;
            c.intersection += inA && inB;
            c.unionCount += inA || inB;
            if (inA && !inB && !nearInside(b, x, y)) ++c.farFromB;
            if (inB && !inA && !nearInside(a, x, y)) ++c.farFromA;
        }
    }
    c.iou = c.unionCount == 0 ? 1.0 : double(c.intersection) / double(c.unionCount);
    return c;
}

std::string describe(const MaskComparison& c) {
    char text[200];
    std::snprintf(text, sizeof text,
                  "iou %.4f (A %lld, B %lld, both %lld, far from B %lld, far from A %lld)", c.iou,
                  static_cast<long long>(c.countA), static_cast<long long>(c.countB),
                  static_cast<long long>(c.intersection), static_cast<long long>(c.farFromB),
                  static_cast<long long>(c.farFromA));
    return text;
}

Image differenceImage(const Mask& a, const Mask& b) {
    checkSameSize(a, b);
    Image image(a.width, a.height);
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            const bool inA = a.at(x, y), inB = b.at(x, y);
            image.at(x, y) =
                Rgba{inA ? 1.0f : 0.0f, inA && inB ? 1.0f : 0.0f, inB ? 1.0f : 0.0f, 1.0f};
        }
    }
    return image;
}

}  // namespace quaternia
