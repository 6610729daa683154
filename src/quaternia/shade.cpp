#include "shade.h"

#include <algorithm>
#include <cmath>

namespace quaternia {
namespace {

double clamp01(double v) {
    return std::clamp(v, 0.0, 1.0);
}
double smoothstep(double a, double b, double v) {
    double t = clamp01((v - a) / (b - a));
    return t * t * (3 - 2 * t);
}

}  // namespace

Shader::Shader(const ShadingSettings& settings, const Fractal& fractal)
    : settings_(settings),
      fractal_(fractal),
      lightDirection_(normalize(settings.lightDirection)),
      fillDirection_(normalize(settings.fillDirection)),
      // Occlusion is probed over a few percent of the object's size: the scale of its folds.
      occlusionStep_(0.025 * fractal.boundingRadius()) {}

double Shader::shadow(const Point3d& p, ShadingStats& stats) const {
    if (settings_.shadows == Shadows::None) return 1;
    Ray ray{p, lightDirection_};
    auto interval = intersectSphere(ray, fractal_.boundingRadius());
    if (!interval) return 1;
    const double minimumStep = 1e-4 * fractal_.boundingRadius();
    const bool soft = settings_.shadows == Shadows::Soft;
    double visibility = 1;
    double t = 0;
    for (int steps = 0; steps < 256 && t < interval->tFar; ++steps) {
        DistanceEstimate e = fractal_.estimate(ray.at(t));
        ++stats.estimates;
        stats.iterations += e.iterations;
        if (e.inside || e.distance < 0.5 * minimumStep) return 0;
        // The penumbra: how nearly the shadow ray grazed the set relative to how far it went.
        if (soft && t > 0)
            visibility = std::min(visibility, settings_.shadowSoftness * e.distance / t);
        t += std::max(e.distance, minimumStep);
    }
    return soft ? smoothstep(0, 1, visibility) : 1;
}

double Shader::ambientOcclusion(const Point3d& p, const Vector3d& normal,
                                ShadingStats& stats) const {
    // Compare the estimate at a few heights h above the surface with h itself. The estimate
    // runs at 0.5 to 1 times the true distance near the set, so a ratio of 0.5 counts as open.
    double open = 0, weights = 0, weight = 1;
    for (int k = 1; k <= 5; ++k) {
        double h = occlusionStep_ * k;
        DistanceEstimate e = fractal_.estimate(p + normal * h);
        ++stats.estimates;
        stats.iterations += e.iterations;
        open += weight * clamp01(2 * e.distance / h);
        weights += weight;
        weight *= 0.7;
    }
    return open / weights;
}

Color Shader::albedo(const DistanceEstimate& estimate) const {
    switch (settings_.coloring) {
        case Coloring::Solid:
            return settings_.baseColor;
        case Coloring::Iteration: {
            double phase = 0.5 + 0.5 * std::cos(0.45 * estimate.smoothIteration);
            return lerp(settings_.baseColor, settings_.accentColor, phase);
        }
        case Coloring::OrbitTrap:
        default: {
            // The orbit's closest approach to 0, relative to the set's size.
            double v = smoothstep(0.15, 0.75, estimate.trap / fractal_.set().escapeRadius());
            return lerp(settings_.accentColor, settings_.baseColor, v);
        }
    }
}

Color Shader::shade(const Hit& hit, const Ray& ray, double footprint, ShadingStats& stats) const {
    Vector3d n = fractal_.normal(hit.outside);
    if (dot(n, ray.direction) > 0) n = -n;  // seen from inside a thin sheet
    Color base = albedo(hit.estimate);
    // Leave the surface by a few footprints so the shadow ray does not hit its own surface.
    Point3d lifted = hit.outside + n * (2 * footprint + 1e-6 * fractal_.boundingRadius());
    double keyDiffuse = std::max(0.0, dot(n, lightDirection_));
    double visibility = keyDiffuse > 0 ? shadow(lifted, stats) : 0;
    double occlusion =
        settings_.ambientOcclusion > 0
            ? 1 - settings_.ambientOcclusion * (1 - ambientOcclusion(hit.outside, n, stats))
            : 1;
    Vector3d halfway = normalize(lightDirection_ - ray.direction);
    double highlight =
        keyDiffuse > 0 ? std::pow(std::max(0.0, dot(n, halfway)), settings_.shininess) : 0;
    double fillDiffuse = std::max(0.0, dot(n, fillDirection_));

    Color color = base * settings_.lightColor * (keyDiffuse * visibility);
    color += settings_.lightColor * (settings_.specular * highlight * visibility);
    color += base * settings_.fillColor * (fillDiffuse * occlusion);
    color += base * (settings_.ambient * occlusion);
    return color;
}

Color Shader::background(const Ray& ray) const {
    double v = 0.5 + 0.5 * ray.direction.y;
    return lerp(settings_.backgroundBottom, settings_.backgroundTop, v);
}

Color Shader::toDisplay(const Color& linear) const {
    auto encode = [&](double v) {
        return std::pow(clamp01(v * settings_.exposure), 1.0 / settings_.gamma);
    };
    return {encode(linear.x), encode(linear.y), encode(linear.z)};
}

}  // namespace quaternia
