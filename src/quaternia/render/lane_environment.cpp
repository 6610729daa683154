#include "quaternia/render/lane_environment.h"

#include <limits>
#include <span>

#include "quaternia/render/ground_lighting.h"

namespace quaternia {

void EnvironmentShadows::light(const LaneFractal& lanes, const Shader& shader,
                               const std::vector<EnvironmentPoint>& points, ShadowRays& shadows,
                               LaneCounters& counters) {
    const Environment& environment = *shader.environment();
    const size_t count = points.size();
    const size_t k = size_t(environment.samples());
    directions_.resize(count * k);
    visibility_.assign(count * k, 1.0);
    shadows.clear();
    const LightSource& towards = shader.environmentShadows();
    for (size_t p = 0; p < count && k > 0; ++p) {
        const EnvironmentPoint& point = points[p];
        const std::span<EnvironmentDirection> rays(directions_.data() + p * k, k);
        environment.shadowDirections(Environment::seedOf(point.point), point.normal, rays);
        for (size_t r = 0; r < k; ++r) {
            if (!(rays[r].weight > 0)) continue;
            const KeyLight at{rays[r].direction, 1, std::numeric_limits<double>::infinity()};
            const Ray ray{point.origin, at.toLight};
            auto interval = shader.shadowIntervalOf(ray, at, towards);
            if (!interval) continue;
            shadows.push(ray, interval->tNear, interval->tFar, int(p * k + r));
        }
    }
    if (shadows.size() > 0) {
        shadows.march(lanes, shadowMarchOf(towards, shader), counters);
        for (size_t r = 0; r < shadows.size(); ++r)
            visibility_[size_t(shadows.owners()[r])] = shadows.visibility()[r];
    }
    colour_.resize(count);
    normals_.resize(count);
    for (size_t p = 0; p < count; ++p)
        normals_[p] = points[p].normal;
    environment.diffuseBatch(normals_, colour_);
    for (size_t p = 0; p < count; ++p)
        colour_[p] = points[p].albedo * colour_[p] *
                     Environment::openFraction(
                         std::span<const EnvironmentDirection>(directions_.data() + p * k, k),
                         std::span<const double>(visibility_.data() + p * k, k));
}

}  // namespace quaternia
