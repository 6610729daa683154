#include "quaternia/cellmap/undecided_band.h"

#include <algorithm>

namespace quaternia {

UndecidedBand measureUndecidedBand(const std::vector<uint8_t>& classes, int width, int height) {
    UndecidedBand band;
    const size_t count = size_t(width) * size_t(height);
    if (classes.size() != count || count == 0) return band;
    auto undecided = [&](int x, int y) {
        return x >= 0 && y >= 0 && x < width && y < height &&
               classes[size_t(y) * size_t(width) + size_t(x)] != 0 &&
               classes[size_t(y) * size_t(width) + size_t(x)] != 255;
    };
    // Run length through each pixel along a direction: forward and backward counts, summed.
    std::vector<int> shortest(count, 0);
    const int directions[4][2] = {{1, 0}, {0, 1}, {1, 1}, {1, -1}};
    std::vector<int> before(count), after(count);
    for (const auto& d : directions) {
        const int dx = d[0], dy = d[1];
        // Forward pass in an order where (x - dx, y - dy) comes first, backward pass in reverse.
        auto visit = [&](bool forward) {
            for (int n = 0; n < height; ++n) {
                const int y = (forward == (dy >= 0)) ? n : height - 1 - n;
                for (int m = 0; m < width; ++m) {
                    const int x = forward ? m : width - 1 - m;
                    const size_t at = size_t(y) * size_t(width) + size_t(x);
                    if (!undecided(x, y)) {
                        (forward ? before : after)[at] = 0;
                        continue;
                    }
                    const int px = forward ? x - dx : x + dx, py = forward ? y - dy : y + dy;
                    const int previous =
                        undecided(px, py)
                            ? (forward ? before : after)[size_t(py) * size_t(width) + size_t(px)]
                            : 0;
                    (forward ? before : after)[at] = previous + 1;
                }
            }
        };
        visit(true);
        visit(false);
        for (size_t at = 0; at < count; ++at) {
            if (before[at] == 0) continue;
            const int run = before[at] + after[at] - 1;
            shortest[at] = shortest[at] == 0 ? run : std::min(shortest[at], run);
        }
    }
    std::vector<int> widths;
    for (int s : shortest)
        if (s > 0) widths.push_back(s);
    band.pixels = int64_t(widths.size());
    if (widths.empty()) return band;
    std::sort(widths.begin(), widths.end());
    band.median = widths[widths.size() / 2];
    band.p99 = widths[std::min(widths.size() - 1, widths.size() * 99 / 100)];
    band.max = widths.back();
    return band;
}

}  // namespace quaternia
