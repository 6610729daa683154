#include "quaternia/render/adaptive_sampling.h"

#include <algorithm>
#include <cmath>

namespace quaternia {
namespace {

// Neighbours whose first samples' display colours differ by more than this in some channel
// (display values in [0, 1]) refine: below it, the pixel's first sample stays within a few
// levels of its full mean.
constexpr float kColourThreshold = 6.0f / 255.0f;

bool differ(const PixelSamples& a, const Rgba& aDisplay, const PixelSamples& b,
            const Rgba& bDisplay) {
    if (a.hits != b.hits) return true;
    if (a.hits == 0) return false;  // both background, which the pixel centre gives
    return std::abs(aDisplay.r - bDisplay.r) > kColourThreshold ||
           std::abs(aDisplay.g - bDisplay.g) > kColourThreshold ||
           std::abs(aDisplay.b - bDisplay.b) > kColourThreshold;
}

}  // namespace

int adaptiveFirstSamples(int samples) {
    return std::min(samples, 1);
}

int adaptiveSampleIndex(int j, int samples) {
    // The strata form columns x rows as in samplePosition; the centre one is (columns / 2,
    // rows / 2).
    const int columns = int(std::ceil(std::sqrt(double(samples))));
    const int rows = (samples + columns - 1) / columns;
    const int centre = std::min(samples - 1, rows / 2 * columns + columns / 2);
    if (j == 0) return centre;
    return j <= centre ? j - 1 : j;
}

Tile refinementRegion(const Tile& tile, int imageWidth, int imageHeight) {
    return Tile{std::max(0, tile.x0 - 1), std::max(0, tile.y0 - 1),
                std::min(imageWidth, tile.x1 + 1), std::min(imageHeight, tile.y1 + 1)};
}

void markPixelsToRefine(const Tile& region, const Tile& tile,
                        const std::vector<PixelSamples>& firstPass, const Shader& shader,
                        std::vector<Rgba>& display, std::vector<uint8_t>& refine) {
    const int regionWidth = region.x1 - region.x0;
    // The display colour of each pixel's hits (the decision is about what the picture shows).
    display.resize(firstPass.size());
    for (size_t i = 0; i < firstPass.size(); ++i) {
        const PixelSamples& p = firstPass[i];
        const Color mean = p.hits > 0 ? p.sum / double(p.hits) : Color();
        display[i] = Rgba{float(mean.x), float(mean.y), float(mean.z), 1.0f};
    }
    shader.toDisplay(display.data(), display.size());
    const int width = tile.x1 - tile.x0;
    refine.assign(size_t(width) * size_t(tile.y1 - tile.y0), 0);
    for (int y = tile.y0; y < tile.y1; ++y) {
        for (int x = tile.x0; x < tile.x1; ++x) {
            const size_t i = size_t(y - region.y0) * size_t(regionWidth) + size_t(x - region.x0);
            const PixelSamples& p = firstPass[i];
            bool disagree = p.hits > 0 && p.hits < p.samples;
            for (int ny = std::max(region.y0, y - 1);
                 !disagree && ny <= std::min(region.y1 - 1, y + 1); ++ny) {
                for (int nx = std::max(region.x0, x - 1); nx <= std::min(region.x1 - 1, x + 1);
                     ++nx) {
                    const size_t n =
                        size_t(ny - region.y0) * size_t(regionWidth) + size_t(nx - region.x0);
                    if (n != i && differ(p, display[i], firstPass[n], display[n])) {
                        disagree = true;
                        break;
                    }
                }
            }
            refine[size_t(y - tile.y0) * size_t(width) + size_t(x - tile.x0)] = disagree;
        }
    }
}

}  // namespace quaternia
