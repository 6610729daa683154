#include "quaternia/cellmap/undecided_band.h"

#include <algorithm>

namespace quaternia {

UndecidedBand measureUndecidedBand(const std::vector<uint8_t>& classes, int width, int height) {
    UndecidedBand band;
    const size_t count = size_t(width) * size_t(height);
    if (classes.size() != count || count == 0) return band;
    auto undecided = [&](int x, int y) {
        if (x < 0 || y < 0 || x >= width || y >= height) return false;
        const uint8_t v = classes[size_t(y) * size_t(width) + size_t(x)];
        return v != 0 && v != 255;
    };
    // Walked from each undecided pixel both ways along each direction, at most kLongest steps
    // (a run that long is reported as kLongest): memory for the widths alone, time for the
    // band's pixels times its width.
    constexpr int kLongest = 1 << 16;
    const int directions[4][2] = {{1, 0}, {0, 1}, {1, 1}, {1, -1}};
    std::vector<int> widths;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            if (!undecided(x, y)) continue;
            int shortest = kLongest;
            for (const auto& d : directions) {
                int run = 1;
                for (int s = 1; run < shortest && undecided(x + s * d[0], y + s * d[1]); ++s)
                    ++run;
                for (int s = 1; run < shortest && undecided(x - s * d[0], y - s * d[1]); ++s)
                    ++run;
                shortest = std::min(shortest, run);
            }
            widths.push_back(shortest);
        }
    band.pixels = int64_t(widths.size());
    if (widths.empty()) return band;
    std::sort(widths.begin(), widths.end());
    band.median = widths[widths.size() / 2];
    band.p99 = widths[std::min(widths.size() - 1, widths.size() * 99 / 100)];
    band.max = widths.back();
    return band;
}

}  // namespace quaternia
