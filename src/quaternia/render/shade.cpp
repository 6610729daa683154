#include "quaternia/render/shade.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "quaternia/render/lanes/shading_lanes.h"

namespace quaternia {

#include "quaternia/render/lanes/lighting-inl.h"  // the lighting formulas, shared with the lanes

namespace {

// lighting-inl.h's arithmetic in double.
struct ScalarLightMath {
    double shininess, highlightCutoff;
    static double set(double x) { return x; }
    static double mulAdd(double a, double b, double c) { return a * b + c; }
    static double max(double a, double b) { return std::max(a, b); }
    static double sqrt(double a) { return std::sqrt(a); }
    double highlight(double gate, double cosine) const {
        return gate > 0 && cosine > highlightCutoff ? std::pow(cosine, shininess) : 0;
    }
};

LightVector<double> lightVector(const Vector3d& v) {
    return {v.x, v.y, v.z};
}

double clamp01(double v) {
    return std::clamp(v, 0.0, 1.0);
}
double smoothstep(double a, double b, double v) {
    double t = clamp01((v - a) / (b - a));
    return t * t * (3 - 2 * t);
}

}  // namespace

Shader::Shader(const ShadingSettings& settings, const Fractal& fractal,
               std::span<const LightSettings> extraLights,
               std::shared_ptr<const Environment> environment)
    : settings_(settings),
      fractal_(fractal),
      environment_(std::move(environment)),
      boundingRadius_(fractal.boundingRadius()),
      lightDirection_(normalize(settings.lightDirection)),
      fillDirection_(normalize(settings.fillDirection)),
      // Occlusion is probed over a few percent of the object's size: the scale of its folds.
      occlusionStep_(0.025 * boundingRadius_),
      highlightCutoff_(std::pow(1e-7, 1 / std::max(settings.shininess, 1e-3))) {
    // The key light: settings_'s own keys, its penumbra from shadow_softness.
    // The key light: [shading]'s keys as a light of [lightN]; without a size (radius or angular
    // radius 0) its soft shadows keep shadow_softness.
    LightSettings keySettings;
    keySettings.enabled = true;
    keySettings.kind = settings.lightKind;
    keySettings.direction = settings.lightDirection;
    keySettings.position = settings.lightPosition;
    keySettings.color = settings.lightColor;
    keySettings.intensity = settings.lightIntensity;
    keySettings.spotTarget = settings.spotTarget;
    keySettings.spotAngle = settings.spotAngle;
    keySettings.spotSoftness = settings.spotSoftness;
    keySettings.shadows = settings.shadows;
    keySettings.radius = settings.lightRadius;
    keySettings.angularRadius = settings.lightAngularRadius;
    LightSource key = lightSourceOf(keySettings);
    const bool sized = settings.lightKind == LightKind::Directional
                           ? settings.lightAngularRadius > 0
                           : settings.lightRadius > 0;
    if (!sized) {
        key.shadows = settings.shadows;
        key.softness = settings.shadowSoftness;
    }
    lights_.push_back(key);
    for (const LightSettings& light : extraLights)
        if (light.enabled) lights_.push_back(lightSourceOf(light));
    if (environment_ && environment_->sun()) lights_.push_back(lightSourceOf(*environment_->sun()));
    environmentShadows_.kind = LightKind::Directional;
    environmentShadows_.shadows = Shadows::Hard;
    // Infinitely far, the background is all fog.
    if (settings_.fogDensity > 0)
        settings_.backgroundTop = settings_.backgroundBottom = settings_.fogColor;
    // Weights 0.7^(k-1), normalised.
    double weight = 1, weights = 0;
    for (int k = 1; k <= kOcclusionSamples; ++k) {
        occlusionScale_[k - 1] = 2 / occlusionHeight(k);
        occlusionWeight_[k - 1] = weight;
        weights += weight;
        weight *= 0.7;
    }
    for (double& w : occlusionWeight_)
        w /= weights;
}

double Shader::shadowMinimumStep() const {
    return 1e-4 * boundingRadius_;
}

double Shader::visibilityFromMarch(double marched) const {
    return visibilityOf(keySource(), marched);
}

double Shader::visibilityOf(const LightSource& light, double marched) const {
    return light.shadows == Shadows::Soft ? smoothstep(0, 1, marched) : marched;
}

LightSource lightSourceOf(const LightSettings& settings) {
    LightSource light;
    light.kind = settings.kind;
    light.direction = normalize(settings.direction);
    light.position = Point3d(settings.position);
    light.color = settings.color;
    light.intensity = settings.intensity;
    if (settings.kind == LightKind::Spot) {
        light.spotAxis = normalize(settings.spotTarget - settings.position);
        light.spotCosOuter = std::cos(settings.spotAngle * M_PI / 180);
        light.spotCosInner =
            std::cos(settings.spotAngle * (1 - settings.spotSoftness) * M_PI / 180);
    }
    // Quilez's penumbra min k h / t is the fraction of a light of angular radius 1 / k that a
    // point sees past an occluder at distance h from the ray, t along it (small angles). A
    // sphere of radius r at distance D subtends r / D: k = D / r, D taken from the set's centre
    // (the origin) to the light. No size: hard shadows.
    light.shadows = settings.shadows;
    const double angle = settings.kind == LightKind::Directional
                             ? std::tan(settings.angularRadius * M_PI / 180)
                             : settings.radius / std::max(length(settings.position), 1e-9);
    if (light.shadows == Shadows::Soft && !(angle > 0)) light.shadows = Shadows::Hard;
    light.softness = angle > 0 ? 1 / angle : 1;
    return light;
}

KeyLight Shader::illumination(const LightSource& light, const Point3d& x) {
    KeyLight key;
    if (light.kind == LightKind::Directional) {
        key.toLight = light.direction;
        key.scale = light.intensity;
        key.distance = std::numeric_limits<double>::infinity();
        return key;
    }
    // A point light's irradiance falls with the inverse square of the distance.
    const Vector3d toLight = light.position - x;
    key.distance = length(toLight);
    key.toLight = toLight / key.distance;
    key.scale = light.intensity / (key.distance * key.distance);
    if (light.kind == LightKind::Spot) {
        // Full within the inner cone, dark beyond the outer, a smoothstep between.
        const double cosine = -dot(key.toLight, light.spotAxis);
        key.scale *= cosine >= light.spotCosInner ? 1
                     : cosine <= light.spotCosOuter
                         ? 0
                         : smoothstep(light.spotCosOuter, light.spotCosInner, cosine);
    }
    return key;
}

std::optional<RayInterval> Shader::shadowInterval(const Ray& ray, const KeyLight& key) const {
    return shadowIntervalOf(ray, key, keySource());
}

std::optional<RayInterval> Shader::shadowIntervalOf(const Ray& ray, const KeyLight& key,
                                                    const LightSource& light) const {
    // From outside the bounding sphere (the ground), a soft shadow's penumbra reaches past the
    // sphere's own shadow: a ray that passes within t / k of the set at t is partly shadowed.
    // Such rays come within (|origin| + R) / k of the sphere, which is grown by that much.
    const double radius = boundingRadius_;
    const double distance = length(ray.origin);
    const double grown = light.shadows == Shadows::Soft && distance > radius
                             ? radius + (distance + radius) / light.softness
                             : radius;
    auto interval = intersectSphere(ray, grown);
    if (!interval) return std::nullopt;
    // A point light's distance from the ray's own origin (a shadow origin lies a little off the
    // surface point the key light was taken at).
    const double toLight =
        light.kind == LightKind::Directional ? key.distance : length(light.position - ray.origin);
    interval->tFar = std::min(interval->tFar, toLight);
    if (!(interval->tNear < interval->tFar)) return std::nullopt;
    return interval;
}

double Shader::shadow(const Point3d& p, const KeyLight& key, ShadingStats& stats) const {
    return shadowOf(p, key, keySource(), stats);
}

double Shader::shadowOf(const Point3d& p, const KeyLight& key, const LightSource& light,
                        ShadingStats& stats) const {
    if (light.shadows == Shadows::None) return 1;
    Ray ray{p, key.toLight};
    auto interval = shadowIntervalOf(ray, key, light);
    if (!interval) return 1;
    if (fractal_.distanceKind() == DistanceKind::kLipschitz)
        return lipschitzShadow(ray, *interval, stats);
    const bool soft = light.shadows == Shadows::Soft;
    const double minimumStep = shadowMinimumStep();
    double visibility = 1;
    double t = interval->tNear;
    // Over-relaxed sphere tracing (Keinert et al. 2014): steps of shadowRelaxation() times the
    // estimate while the balls of consecutive points overlap; where they do not, the step may
    // have jumped over the set, so go back to the plain step.
    double relaxation = 1, radius = 0, step = 0;
    for (int steps = 0; steps < kShadowSteps && t < interval->tFar; ++steps) {
        DistanceEstimate e = fractal_.estimate(ray.at(t));
        ++stats.estimates;
        stats.iterations += e.iterations;
        if (relaxation > 1 && radius + e.distance < step) {
            t += radius - step;
            step = radius;
            relaxation = 1;
            continue;
        }
        if (e.inside || e.distance < 0.5 * minimumStep) return 0;
        // The penumbra: how nearly the shadow ray grazed the set relative to how far it went.
        if (soft && t > 0) visibility = std::min(visibility, light.softness * e.distance / t);
        const double newRadius = std::max(e.distance, minimumStep);
        relaxation = shadowRelaxation(radius, newRadius, step);
        radius = newRadius;
        step = relaxation * radius;
        t += step;
    }
    return visibilityOf(light, soft ? visibility : 1);
}

double Shader::lipschitzShadow(const Ray& ray, const RayInterval& interval,
                               ShadingStats& stats) const {
    // The distance is a proven bound but far below the true distance near the set, so neither
    // a penumbra nor a stop on a small distance means anything: Algorithm 2's fixed steps of a
    // thousandth of the bounding radius (crossing proven empty space at once, march.h), and a
    // hard shadow wherever a sample lies in K_N.
    const double fixedStep = 1e-3 * boundingRadius_;
    const SampleCrossing crossing = firstSampleInside(fractal_, ray, 2 * fixedStep, interval.tFar,
                                                      fixedStep, std::numeric_limits<int>::max());
    stats.estimates += crossing.steps;
    stats.iterations += crossing.iterations;
    return crossing.tInside ? 0 : 1;
}

double Shader::ambientOcclusion(const Point3d& p, const Vector3d& normal,
                                ShadingStats& stats) const {
    // Occlusion compares estimates with heights: a bound far below the distance would read as
    // a closed crease everywhere, so the sets without an estimate are lit as open.
    if (fractal_.distanceKind() == DistanceKind::kLipschitz) return 1;
    double distances[kOcclusionSamples];
    for (int k = 1; k <= kOcclusionSamples; ++k) {
        DistanceEstimate e = fractal_.estimate(p + normal * occlusionHeight(k));
        ++stats.estimates;
        stats.iterations += e.iterations;
        distances[k - 1] = e.distance;
    }
    return occlusionFromEstimates(distances);
}

double Shader::occlusionFromEstimates(const double* distances) const {
    // Compare the estimate at a few heights h above the surface with h itself. The estimate
    // runs at 0.5 to 1 times the true distance near the set, so a ratio of 0.5 counts as open.
    // The weights fall by 0.7 per sample (occlusionWeight_), and sum to 1.
    double open = 0;
    for (int k = 0; k < kOcclusionSamples; ++k)
        open += occlusionWeight_[k] * clamp01(distances[k] * occlusionScale_[k]);
    return open;
}

double Shader::ambientFromOpenness(double open) const {
    return 1 - settings_.ambientOcclusion * (1 - open);
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
            double v = smoothstep(0.15, 0.75, estimate.trap / fractal_.escapeRadius());
            return lerp(settings_.accentColor, settings_.baseColor, v);
        }
    }
}

Color Shader::shade(const Hit& hit, const Ray& ray, double footprint, ShadingStats& stats,
                    SurfaceSample* surface, bool occlusion) const {
    SurfaceSample sample;
    sample.normal = fractal_.normal(hit.outside);
    if (dot(sample.normal, ray.direction) > 0) sample.normal = -sample.normal;  // a thin sheet
    sample.albedo = albedo(hit.estimate);
    const KeyLight key = keyLight(hit.outside);
    sample.toLight = key.toLight;
    sample.keyScale = key.scale;
    sample.visibility =
        keyDiffuse(sample.normal, key) > 0
            ? shadow(shadowOrigin(hit.outside, sample.normal, footprint), key, stats)
            : 0;
    sample.occlusion =
        occlusion && occlusionEnabled()
            ? ambientFromOpenness(ambientOcclusion(hit.outside, sample.normal, stats))
            : 1;
    if (surface) *surface = sample;
    Color color = light(sample, ray);
    for (const LightSource& other : extraLights()) {
        const KeyLight at = illumination(other, hit.outside);
        if (!(keyDiffuse(sample.normal, at) > 0)) continue;
        const double visibility =
            shadowOf(shadowOrigin(hit.outside, sample.normal, footprint), at, other, stats);
        color += lightOther(other, at, sample.normal, sample.albedo, ray.direction, visibility);
    }
    if (environmentLighting())
        color += environmentLight(hit.outside, shadowOrigin(hit.outside, sample.normal, footprint),
                                  sample.normal, sample.albedo, stats);
    return color;
}

Color Shader::environmentLight(const Point3d& point, const Point3d& origin, const Vector3d& n,
                               const Color& albedo, ShadingStats& stats) const {
    const int count = environment_->samples();
    std::array<EnvironmentDirection, kMaxEnvironmentSamples> directions;
    std::array<double, kMaxEnvironmentSamples> visibility;
    const std::span<EnvironmentDirection> rays(directions.data(), size_t(count));
    environment_->shadowDirections(Environment::seedOf(point), n, rays);
    for (int k = 0; k < count; ++k) {
        visibility[size_t(k)] = 1;
        if (!(directions[size_t(k)].weight > 0)) continue;
        const KeyLight towards{directions[size_t(k)].direction, 1,
                               std::numeric_limits<double>::infinity()};
        visibility[size_t(k)] = shadowOf(origin, towards, environmentShadows_, stats);
    }
    return environment_->occludedDiffuse(n, albedo, rays,
                                         std::span<const double>(visibility.data(), size_t(count)));
}

Color Shader::lightOther(const LightSource& light, const KeyLight& at, const Vector3d& normal,
                         const Color& albedo, const Vector3d& view, double visibility) const {
    if (!(keyDiffuse(normal, at) > 0) || !(visibility > 0)) return Color();
    const LightVector<double> lit =
        litByOther(ScalarLightMath{settings_.shininess, highlightCutoff_}, lightVector(normal),
                   lightVector(at.toLight), lightVector(view), at.scale, visibility,
                   lightVector(albedo), lightVector(light.color), settings_.specular);
    return {lit.x, lit.y, lit.z};
}

Color Shader::light(const SurfaceSample& sample, const Ray& ray) const {
    const LightVector<double> lit =
        litByKey(ScalarLightMath{settings_.shininess, highlightCutoff_}, lightVector(sample.normal),
                 lightVector(sample.toLight), lightVector(ray.direction), sample.keyScale,
                 sample.visibility, sample.occlusion, lightVector(sample.albedo),
                 lightVector(fillDirection_), lightVector(settings_.lightColor),
                 lightVector(settings_.fillColor), settings_.specular, settings_.ambient);
    return {lit.x, lit.y, lit.z};
}

LightConstants Shader::lightConstants() const {
    auto put = [](float* out, const Vector3d& v) {
        out[0] = float(v.x), out[1] = float(v.y), out[2] = float(v.z);
    };
    LightConstants k;
    put(k.fill, fillDirection_);
    put(k.lightColor, settings_.lightColor);
    put(k.fillColor, settings_.fillColor);
    k.specular = float(settings_.specular);
    k.shininess = float(settings_.shininess);
    k.ambient = float(settings_.ambient);
    k.highlightCutoff = float(highlightCutoff_);
    return k;
}

bool Shader::environmentBackground() const {
    return environment_ && environment_->background() && !(settings_.fogDensity > 0);
}

Color Shader::background(const Ray& ray, double spread) const {
    if (environmentSeen()) return environment_->radiance(ray.direction, spread);
    double v = 0.5 + 0.5 * ray.direction.y;
    return lerp(settings_.backgroundBottom, settings_.backgroundTop, v);
}

void Shader::backgroundRow(const Vector3d& first, const Vector3d& step, int x0, int count,
                           float alpha, Rgba* out) const {
    if (environmentBackground()) {
        environment_->radianceRow(first, step, x0, count, alpha, out);
        return;
    }
    // The direction's y and its length, as background() takes them from the normalised ray.
    const float ax = float(first.x), ay = float(first.y), az = float(first.z);
    const float bx = float(step.x), by = float(step.y), bz = float(step.z);
    const Color& bottom = settings_.backgroundBottom;
    const Color& top = settings_.backgroundTop;
    const float r0 = float(bottom.x), g0 = float(bottom.y), b0 = float(bottom.z);
    const float dr = float(top.x - bottom.x), dg = float(top.y - bottom.y),
                db = float(top.z - bottom.z);
    for (int i = 0; i < count; ++i) {
        const float px = float(x0 + i);
        const float x = ax + px * bx, y = ay + px * by, z = az + px * bz;
        const float v = 0.5f + 0.5f * y / std::sqrt(x * x + y * y + z * z);
        out[i] = Rgba{r0 + v * dr, g0 + v * dg, b0 + v * db, alpha};
    }
}

void Shader::toDisplay(Rgba* pixels, size_t count) const {
    static_assert(sizeof(Rgba) == 4 * sizeof(float), "Rgba is four packed floats");
    encodeDisplay(&pixels->r, count, float(settings_.exposure), float(1.0 / settings_.gamma));
}

Color Shader::toDisplay(const Color& linear) const {
    // In float: the result goes to 8 or 16 bits, and powf is several times faster than pow.
    const float inverseGamma = float(1.0 / settings_.gamma);
    auto encode = [&](double v) {
        return double(std::pow(float(clamp01(v * settings_.exposure)), inverseGamma));
    };
    return {encode(linear.x), encode(linear.y), encode(linear.z)};
}

}  // namespace quaternia
