// What the plane tests share (plane_certificate_test.cpp, plane_cells_test.cpp): the basilica's
// and the rabbit's c, work on a number of threads, and a plane scene of a kind and size drawn
// with one sample per pixel (its centre).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_file.h"
#include "quaternia/util/parallel.h"

namespace quaternia::testing {

inline const std::vector<double> kBasilica = {-1, 0, 0, 0};
inline const std::vector<double> kRabbit = {-0.122561, 0.744862, 0, 0};

inline WorkOptions onThreads(int threads) {
    WorkOptions options;
    options.threads = threads;
    return options;
}

inline Scene planeTestScene(const std::string& kind, const std::vector<double>& c, int width,
                            int height) {
    Scene scene = defaultScene();
    setParameter(scene, "plane.kind", kind);
    setParameter(scene, "fractal.c", c);
    setParameter(scene, "render.width", int64_t{width});
    setParameter(scene, "render.height", int64_t{height});
    setParameter(scene, "render.samples", int64_t{1});
    return scene;
}

}  // namespace quaternia::testing
