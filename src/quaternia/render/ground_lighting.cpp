#include "quaternia/render/ground_lighting.h"

namespace quaternia {

ShadowMarch shadowMarchOf(const LightSource& light, const Shader& shader) {
    ShadowMarch shadowMarch;
    shadowMarch.minimumStep = shader.shadowMinimumStep();
    shadowMarch.softness = light.softness;
    shadowMarch.soft = light.shadows == Shadows::Soft;
    shadowMarch.maxSteps = Shader::kShadowSteps;
    shadowMarch.relaxation = Shader::kShadowRelaxation;
    shadowMarch.maxRelaxation = Shader::kShadowMaxRelaxation;
    return shadowMarch;
}

void GroundLighting::visibilities(const std::vector<GroundPoint>& points, const Frame& frame,
                                  const LightSource& light, ShadowRays& shadows,
                                  LaneCounters& counters, std::vector<double>& out) const {
    const size_t count = points.size();
    const double offset = 1e-6 * frame.boundingRadius;
    shadows.clear();
    out.assign(count, 1.0);
    if (light.shadows == Shadows::None) return;
    // A directional light is the same at every point.
    const bool directional = light.kind == LightKind::Directional;
    KeyLight at = Shader::illumination(light, Point3d());
    for (size_t g = 0; g < count; ++g) {
        const GroundPoint& p = points[g];
        if (!directional) at = Shader::illumination(light, p.x);
        const Vector3d n = p.normal();
        if (!(Shader::keyDiffuse(n, at) > 0)) continue;
        const Ray ray{p.x + n * offset, at.toLight};
        auto interval = frame.shader.shadowIntervalOf(ray, at, light);
        if (!interval) continue;
        shadows.push(ray, interval->tNear, interval->tFar, int(g));
    }
    if (frame.cones) {
        shadows.clearLitByCones(
            frame.lanes, frame.march, light, frame.boundingRadius,
            [&](int point) { return points[size_t(point)].block; }, counters);
    }
    shadows.march(frame.lanes, shadowMarchOf(light, frame.shader), counters);
    for (size_t r = 0; r < shadows.size(); ++r)
        out[size_t(shadows.owners()[r])] =
            frame.shader.visibilityOf(light, shadows.visibility()[r]);
}

void GroundLighting::light(const std::vector<GroundPoint>& points, const Frame& frame,
                           ShadowRays& shadows, LaneCounters& counters) {
    const Shader& shader = frame.shader;
    const Color& albedo = frame.ground.color;
    const size_t count = points.size();
    visibilities(points, frame, shader.keySource(), shadows, counters, keyVisibility_);
    colour_.assign(count, Color());
    for (const LightSource& light : shader.extraLights()) {
        visibilities(points, frame, light, shadows, counters, otherVisibility_);
        for (size_t g = 0; g < count; ++g) {
            const GroundPoint& p = points[g];
            colour_[g] += shader.lightOther(light, Shader::illumination(light, p.x), p.normal(),
                                            albedo, p.direction, otherVisibility_[g]);
        }
    }
    // The key light, in lanes as the set's hits are lit (lightSurfaces).
    SurfaceBatch& lit = surfaces_;
    lit.resize(count);
    const bool directional = shader.keySource().kind == LightKind::Directional;
    KeyLight key = shader.keyLight(Point3d());
    for (size_t g = 0; g < count; ++g) {
        const GroundPoint& p = points[g];
        if (!directional) key = shader.keyLight(p.x);
        const Vector3d n = p.normal();
        const bool facing = Shader::keyDiffuse(n, key) > 0;
        lit.nx[g] = float(n.x), lit.ny[g] = float(n.y), lit.nz[g] = float(n.z);
        lit.dx[g] = float(p.direction.x), lit.dy[g] = float(p.direction.y),
        lit.dz[g] = float(p.direction.z);
        lit.lx[g] = float(key.toLight.x), lit.ly[g] = float(key.toLight.y),
        lit.lz[g] = float(key.toLight.z);
        lit.keyScale[g] = float(key.scale);
        lit.albedoR[g] = float(albedo.x), lit.albedoG[g] = float(albedo.y),
        lit.albedoB[g] = float(albedo.z);
        // Where the key light is behind the plane: no light, and no shadow to catch.
        lit.visibility[g] = facing ? float(keyVisibility_[g]) : 0.0f;
        if (!facing) keyVisibility_[g] = 1;
        lit.occlusion[g] = 1;
    }
    lightSurfaces(frame.lightConstants, lit);
    for (size_t g = 0; g < count; ++g)
        colour_[g] += Color(lit.red[g], lit.green[g], lit.blue[g]);
    if (!shader.environmentLighting()) return;
    const Environment& environment = *shader.environment();
    if (environment.samples() == 0) {
        // Unshadowed: the same light at every point of a side of the plane.
        const Color above = albedo * environment.diffuse({0, 1, 0});
        const Color below = albedo * environment.diffuse({0, -1, 0});
        for (size_t g = 0; g < count; ++g)
            colour_[g] += points[g].normal().y > 0 ? above : below;
        return;
    }
    // The environment's light, shadowed by the set: its contact shadow on the ground.
    const double offset = 1e-6 * frame.boundingRadius;
    environmentPoints_.resize(count);
    for (size_t g = 0; g < count; ++g) {
        const GroundPoint& p = points[g];
        environmentPoints_[g] = {p.x, p.x + p.normal() * offset, p.normal(), albedo};
    }
    environment_.light(frame.lanes, shader, environmentPoints_, shadows, counters);
    for (size_t g = 0; g < count; ++g)
        colour_[g] += environment_.colour()[g];
}

}  // namespace quaternia
