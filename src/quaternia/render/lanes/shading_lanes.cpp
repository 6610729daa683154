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

#include "quaternia/render/lanes/lighting-inl.h"  // the lighting formulas, shared with shade.cpp

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
// lighting-inl.h's arithmetic in float lanes.
template <class D>
struct LaneLightMath {
    using V = hn::Vec<D>;
    D d;
    V shininess, cutoff, tiny;
    V set(double x) const { return hn::Set(d, float(x)); }
    static V mulAdd(V a, V b, V c) { return hn::MulAdd(a, b, c); }
    static V max(V a, V b) { return hn::Max(a, b); }
    static V sqrt(V a) { return hn::Sqrt(a); }
    V highlight(V gate, V cosine) const {
        const auto shines = hn::And(gate > hn::Zero(d), cosine > cutoff);
        return hn::IfThenElseZero(shines,
                                  hn::Exp(d, shininess * hn::Log(d, hn::Max(cosine, tiny))));
    }
};

void LightSurfaceLanes(const LightConstants& k, SurfaceBatch& surfaces) {
    const hn::ScalableTag<float> d;
    using V = hn::Vec<decltype(d)>;
    const size_t lanes = hn::Lanes(d);
    auto set = [&](float v) { return hn::Set(d, v); };
    const LaneLightMath<decltype(d)> math{d, set(k.shininess), set(k.highlightCutoff), set(1e-30f)};
    auto constant = [&](const float* v) { return LightVector<V>{set(v[0]), set(v[1]), set(v[2])}; };
    const LightVector<V> fill = constant(k.fill), lightColor = constant(k.lightColor),
                         fillColor = constant(k.fillColor);
    auto light = [&](size_t i, auto load, auto store) {
        auto vector = [&](const std::vector<float>& x, const std::vector<float>& y,
                          const std::vector<float>& z) {
            return LightVector<V>{load(x, i), load(y, i), load(z, i)};
        };
        const LightVector<V> lit =
            litByKey(math, vector(surfaces.nx, surfaces.ny, surfaces.nz),
                     vector(surfaces.lx, surfaces.ly, surfaces.lz),
                     vector(surfaces.dx, surfaces.dy, surfaces.dz), load(surfaces.keyScale, i),
                     load(surfaces.visibility, i), load(surfaces.occlusion, i),
                     vector(surfaces.albedoR, surfaces.albedoG, surfaces.albedoB), fill, lightColor,
                     fillColor, set(k.specular), set(k.ambient));
        store(lit.x, surfaces.red, i);
        store(lit.y, surfaces.green, i);
        store(lit.z, surfaces.blue, i);
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
