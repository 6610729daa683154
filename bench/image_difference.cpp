// quaternia_image_difference: how far one picture lies from another, in display values.
//   quaternia_image_difference A.png B.png
// prints one line of JSON: the mean absolute difference per channel over every pixel and
// channel (R, G, B, A) and the largest, both in 1/255 units, and how many pixels differ by more
// than 24/255 in some channel (issue 17's bound for adaptive sampling against uniform). Exit
// code 2 with a message on bad input (unreadable files, different sizes).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>

#include "quaternia/image/png_io.h"

int main(int argc, char** argv) {
    using namespace quaternia;
    if (argc != 3) {
        std::fprintf(stderr, "usage: %s A.png B.png\n", argv[0]);
        return 2;
    }
    try {
        const Image a = readPng(argv[1]), b = readPng(argv[2]);
        if (a.width() != b.width() || a.height() != b.height()) {
            std::fprintf(stderr, "quaternia_image_difference: sizes differ (%dx%d, %dx%d)\n",
                         a.width(), a.height(), b.width(), b.height());
            return 2;
        }
        double sum = 0, largest = 0;
        long over = 0;
        for (int y = 0; y < a.height(); ++y) {
            for (int x = 0; x < a.width(); ++x) {
                const Rgba p = a.at(x, y), q = b.at(x, y);
                const double d[4] = {std::abs(p.r - q.r), std::abs(p.g - q.g), std::abs(p.b - q.b),
                                     std::abs(p.a - q.a)};
                const double pixelLargest = *std::max_element(d, d + 4) * 255;
                sum += (d[0] + d[1] + d[2] + d[3]) * 255;
                largest = std::max(largest, pixelLargest);
                over += pixelLargest > 24 + 1e-6;
            }
        }
        const double values = 4.0 * a.width() * a.height();
        std::printf("{\"mean\":%.4f,\"max\":%.2f,\"pixels_over_24\":%ld}\n", sum / values, largest,
                    over);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "quaternia_image_difference: %s\n", e.what());
        return 2;
    }
    return 0;
}
