// quaternia_mask_iou: compares a renderer's silhouette with a reference mask.
//   quaternia_mask_iou RENDER.png alpha|luma REFERENCE.png alpha|luma [--difference OUT.png]
// prints one line of JSON (mask_tool.h); exit code 2 with a message on bad input.
#include <cstdio>
#include <exception>
#include <string>

#include "mask_tool.h"
#include "quaternia/image/png_io.h"

int main(int argc, char** argv) {
    using namespace quaternia;
    if (argc != 5 && !(argc == 7 && std::string(argv[5]) == "--difference")) {
        std::fprintf(stderr,
                     "usage: %s RENDER.png alpha|luma REFERENCE.png alpha|luma "
                     "[--difference OUT.png]\n",
                     argv[0]);
        return 2;
    }
    try {
        Mask a = bench::maskOf(readPng(argv[1]), bench::parseMaskSource(argv[2]));
        Mask b = bench::maskOf(readPng(argv[3]), bench::parseMaskSource(argv[4]));
        MaskComparison comparison = compareMasks(a, b);
        if (argc == 7) writePng(argv[6], differenceImage(a, b), 8);
        std::printf("%s\n", bench::comparisonJson(comparison).c_str());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "quaternia_mask_iou: %s\n", e.what());
        return 2;
    }
    return 0;
}
