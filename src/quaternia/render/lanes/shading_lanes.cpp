// The SIMD lanes of shading_lanes.h, compiled once per instruction set by Highway's
// foreach_target and chosen at run time (HWY_DYNAMIC_DISPATCH), as camera_lanes.cpp.

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "quaternia/render/lanes/shading_lanes.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
// clang-format off: the order matters, highway.h after foreach_target.h
#include <hwy/contrib/math/math-inl.h>
#include <hwy/highway.h>
// clang-format on

#include <algorithm>

#include "quaternia/render/lanes/lane_state.h"
#include "quaternia/render/lanes/shading_lanes.h"

HWY_BEFORE_NAMESPACE();
namespace quaternia {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void EncodeDisplay(float* values, size_t pixels, float exposure, float inverseGamma) {
    const hn::ScalableTag<float> d;
    const size_t lanes = hn::Lanes(d);
    const auto zero = hn::Zero(d), one = hn::Set(d, 1.0f), scale = hn::Set(d, exposure),
               power = hn::Set(d, inverseGamma), tiny = hn::Set(d, 1e-30f);
    auto encode = [&](hn::Vec<decltype(d)> v) {
        v = hn::Min(one, hn::Max(zero, v * scale));
        // v^g = exp(g ln v); v = 0 gives 0.
        return hn::IfThenZeroElse(v <= zero, hn::Exp(d, power * hn::Log(d, hn::Max(v, tiny))));
    };
    // A vector of pixels at a time, split into its channels: the colours are encoded, alpha
    // passes unchanged (and costs nothing).
    auto encodePixels = [&](float* p) {
        hn::Vec<decltype(d)> r, g, b, a;
        hn::LoadInterleaved4(d, p, r, g, b, a);
        hn::StoreInterleaved4(encode(r), encode(g), encode(b), a, d, p);
    };
    size_t i = 0;
    for (; i + lanes <= pixels; i += lanes)
        encodePixels(values + 4 * i);
    if (i < pixels) {
        alignas(kMaxLaneBytes) float tail[4 * kMaxLaneBytes / sizeof(float)] = {};
        std::copy(values + 4 * i, values + 4 * pixels, tail);
        encodePixels(tail);
        std::copy(tail, tail + 4 * (pixels - i), values + 4 * i);
    }
}
void LightSurfaceLanes(const LightConstants& k, SurfaceBatch& surfaces) {
    const hn::ScalableTag<float> d;
    using V = hn::Vec<decltype(d)>;
    const size_t lanes = hn::Lanes(d);
    auto set = [&](float v) { return hn::Set(d, v); };
    const V zero = hn::Zero(d), tiny = set(1e-30f);
    auto light = [&](size_t i, auto load, auto store) {
        const V nx = load(surfaces.nx, i), ny = load(surfaces.ny, i), nz = load(surfaces.nz, i);
        const V lx = load(surfaces.lx, i), ly = load(surfaces.ly, i), lz = load(surfaces.lz, i);
        const V keyScale = load(surfaces.keyScale, i);
        const V key = hn::Max(zero, hn::MulAdd(nz, lz, hn::MulAdd(ny, ly, nx * lx))) * keyScale;
        const V fill = hn::Max(
            zero,
            hn::MulAdd(nz, set(k.fill[2]), hn::MulAdd(ny, set(k.fill[1]), nx * set(k.fill[0]))));
        // The highlight: cos^shininess of the angle between the normal and the halfway vector.
        const V hx = lx - load(surfaces.dx, i), hy = ly - load(surfaces.dy, i),
                hz = lz - load(surfaces.dz, i);
        const V cosine = hn::MulAdd(nz, hz, hn::MulAdd(ny, hy, nx * hx)) /
                         hn::Sqrt(hn::MulAdd(hz, hz, hn::MulAdd(hy, hy, hx * hx)));
        const auto shines = hn::And(key > zero, cosine > set(k.highlightCutoff));
        const V highlight = hn::IfThenElseZero(
            shines, hn::Exp(d, set(k.shininess) * hn::Log(d, hn::Max(cosine, tiny))));
        const V visibility = load(surfaces.visibility, i), occlusion = load(surfaces.occlusion, i);
        const V direct = key * visibility;
        const V shine = set(k.specular) * highlight * keyScale * visibility;
        const V fillLevel = fill * occlusion, ambientLevel = set(k.ambient) * occlusion;
        auto channel = [&](const std::vector<float>& albedo, int c) {
            const V base = load(albedo, i);
            const V lit = hn::MulAdd(direct, set(k.lightColor[c]),
                                     hn::MulAdd(fillLevel, set(k.fillColor[c]), ambientLevel));
            return hn::MulAdd(base, lit, shine * set(k.lightColor[c]));
        };
        store(channel(surfaces.albedoR, 0), surfaces.red, i);
        store(channel(surfaces.albedoG, 1), surfaces.green, i);
        store(channel(surfaces.albedoB, 2), surfaces.blue, i);
    };
    const size_t count = surfaces.size();
    size_t i = 0;
    auto loadU = [&](const std::vector<float>& v, size_t at) {
        return hn::LoadU(d, v.data() + at);
    };
    auto storeU = [&](V v, std::vector<float>& out, size_t at) {
        hn::StoreU(v, d, out.data() + at);
    };
    for (; i + lanes <= count; i += lanes)
        light(i, loadU, storeU);
    if (i < count) {
        const size_t rest = count - i;
        // The last lanes through a zero-padded copy.
        auto loadTail = [&](const std::vector<float>& v, size_t at) {
            alignas(kMaxLaneBytes) float tail[kMaxLaneBytes / sizeof(float)] = {};
            std::copy(v.data() + at, v.data() + at + rest, tail);
            return hn::Load(d, tail);
        };
        auto storeTail = [&](V v, std::vector<float>& out, size_t at) {
            alignas(kMaxLaneBytes) float tail[kMaxLaneBytes / sizeof(float)];
            hn::Store(v, d, tail);
            std::copy(tail, tail + rest, out.data() + at);
        };
        light(i, loadTail, storeTail);
    }
}
}  // namespace HWY_NAMESPACE
}  // namespace quaternia
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace quaternia {

HWY_EXPORT(EncodeDisplay);
HWY_EXPORT(LightSurfaceLanes);

void SurfaceBatch::resize(size_t n) {
    for (auto* v : {&nx, &ny, &nz, &dx, &dy, &dz, &lx, &ly, &lz, &keyScale, &albedoR, &albedoG,
                    &albedoB, &visibility, &occlusion, &red, &green, &blue})
        v->resize(n);
}
void lightSurfaces(const LightConstants& constants, SurfaceBatch& surfaces) {
    HWY_DYNAMIC_DISPATCH(LightSurfaceLanes)(constants, surfaces);
}
void encodeDisplay(float* rgba, size_t pixels, float exposure, float inverseGamma) {
    HWY_DYNAMIC_DISPATCH(EncodeDisplay)(rgba, pixels, exposure, inverseGamma);
}
}  // namespace quaternia
#endif  // HWY_ONCE
