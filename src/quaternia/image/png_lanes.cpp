// The SIMD lanes of png_lanes.h, compiled once per instruction set by Highway's foreach_target
// and chosen at run time (HWY_DYNAMIC_DISPATCH), as shading_lanes.cpp.

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "quaternia/image/png_lanes.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
// clang-format off: the order matters, highway.h after foreach_target.h
#include <hwy/highway.h>
// clang-format on

#include <algorithm>
#include <limits>

#include "quaternia/image/png_lanes.h"
#include "quaternia/util/lane_width.h"

HWY_BEFORE_NAMESPACE();
namespace quaternia {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

static_assert(HWY_MAX_BYTES <= kMaxLaneBytes);
// Pixels of one group (a vector of floats per channel) on the widest target.
constexpr size_t kMaxGroupPixels = kMaxLaneBytes / sizeof(float);

// The nearest of 0 .. MaxValue to `value` clamped to [0, 1] (NaN to 0), halves up: the floor
// of v * MaxValue + 0.5 taken exactly, as png_io's scalar formula gets it in double, here in
// float lanes. First a candidate that is right or one too high, then an exact test of whether
// it is too high.
template <uint32_t MaxValue, class DF>
hn::Vec<hn::RebindToUnsigned<DF>> Quantise(DF df, hn::Vec<DF> value) {
    static_assert(MaxValue == 255 || MaxValue == 65535, "MaxValue + 1 must be a power of two");
    using VF = hn::Vec<DF>;
    const hn::RebindToUnsigned<DF> du;
    const VF zero = hn::Zero(df), one = hn::Set(df, 1.0f), two = hn::Set(df, 2.0f);
    // value > 0 is false for NaN, which therefore becomes 0.
    const VF v = hn::IfThenElseZero(value > zero, hn::Min(value, one));
    // In float the product and the sum each round by at most half a unit in the last place,
    // together less than 2^-8 below 65536. With 1/16 more than a half added, the floor is never
    // below the exact result and at most one above.
    const VF candidate =
        hn::Floor(hn::MulAdd(v, hn::Set(df, float(MaxValue)), hn::Set(df, 0.5f + 1.0f / 16)));
    // The candidate n is one too high iff v * MaxValue + 0.5 < n, iff 2 MaxValue v - (2n - 1) < 0
    // (1 - 2n is exact in float: a small odd integer).
#if HWY_NATIVE_FMA
    // Fused, the sum is rounded once, which keeps its sign.
    const auto tooHigh = hn::MulAdd(v, hn::Set(df, 2.0f * float(MaxValue)),
                                    hn::NegMulAdd(candidate, two, one)) < zero;
#else
    // Unfused, the product would round: instead 2 (MaxValue + 1) v - (2n - 1) < 2 v, where
    // every term is exact: v times a power of two, 2n - 1 and, for n >= 1, their difference (a
    // multiple of the product's unit in the last place that is no larger than the product, since
    // 2n - 1 is at most twice the product). For n = 0 the left side is above 1, the test false.
    const VF scaled = hn::Mul(v, hn::Set(df, 2.0f * (float(MaxValue) + 1.0f)));
    const auto tooHigh = hn::Sub(scaled, hn::MulSub(candidate, two, one)) < hn::Add(v, v);
#endif
    // n + 2^23 (exact, an integer below 2^24) is a float whose bits are those of 2^23 plus n:
    // less those, and one more where n is too high, they are the sample.
    constexpr uint32_t kTwoTo23Bits = 0x4b000000;
    const auto bits = hn::BitCast(du, hn::Add(candidate, hn::Set(df, 8388608.0f)));
    return hn::Sub(bits, hn::IfThenElse(hn::RebindMask(du, tooHigh), hn::Set(du, kTwoTo23Bits + 1),
                                        hn::Set(du, kTwoTo23Bits)));
}

// 16-bit samples with their bytes swapped, so that a little-endian store writes PNG's
// big-endian order.
template <class V>
V ToBigEndian(V samples) {
    return hn::Or(hn::ShiftLeft<8>(samples), hn::ShiftRight<8>(samples));
}

// One group of pixels (a vector of floats per channel, 4 vectors of packed RGBA) to samples of
// Sample (uint8_t or uint16_t); the bytes go to `out`.
template <class Sample, bool WithAlpha>
void QuantiseGroup(const float* HWY_RESTRICT rgba, uint8_t* HWY_RESTRICT out) {
    constexpr uint32_t kMax = std::numeric_limits<Sample>::max();
    const hn::ScalableTag<float> df;
    const hn::Rebind<Sample, decltype(df)> ds;
    const size_t lanes = hn::Lanes(df);
    auto toSamples = [&](hn::Vec<decltype(df)> v) {
        const auto samples = hn::TruncateTo(ds, Quantise<kMax>(df, v));
        if constexpr (sizeof(Sample) == 1) {
            return samples;
        } else {
            return ToBigEndian(samples);
        }
    };
    // Stored through Sample pointers: Highway's stores are unaligned and alias as intrinsics
    // or memcpy do.
    Sample* samplesOut = reinterpret_cast<Sample*>(out);
    if constexpr (WithAlpha) {
        // The samples are in the order of the floats: no interleaving to undo.
        for (size_t k = 0; k < 4; ++k)
            hn::StoreU(toSamples(hn::LoadU(df, rgba + k * lanes)), ds, samplesOut + k * lanes);
    } else {
        hn::Vec<decltype(df)> r, g, b, a;
        hn::LoadInterleaved4(df, rgba, r, g, b, a);
        hn::StoreInterleaved3(toSamples(r), toSamples(g), toSamples(b), ds, samplesOut);
    }
}

template <class Sample, bool WithAlpha>
void QuantisePixels(const float* HWY_RESTRICT rgba, size_t pixels, uint8_t* HWY_RESTRICT out) {
    constexpr size_t kPixelBytes = (WithAlpha ? 4 : 3) * sizeof(Sample);
    const size_t lanes = hn::Lanes(hn::ScalableTag<float>());
    size_t i = 0;
    for (; i + lanes <= pixels; i += lanes)
        QuantiseGroup<Sample, WithAlpha>(rgba + 4 * i, out + kPixelBytes * i);
    if (i < pixels) {
        // The last pixels through a zero-padded copy.
        alignas(kMaxLaneBytes) float tail[4 * kMaxGroupPixels] = {};
        alignas(kMaxLaneBytes) uint8_t tailOut[kPixelBytes * kMaxGroupPixels];
        std::copy(rgba + 4 * i, rgba + 4 * pixels, tail);
        QuantiseGroup<Sample, WithAlpha>(tail, tailOut);
        std::copy(tailOut, tailOut + kPixelBytes * (pixels - i), out + kPixelBytes * i);
    }
}

void QuantisePngSamples(const float* rgba, size_t pixels, int bitDepth, bool withAlpha,
                        uint8_t* out) {
    if (bitDepth == 8 && withAlpha)
        QuantisePixels<uint8_t, true>(rgba, pixels, out);
    else if (bitDepth == 8)
        QuantisePixels<uint8_t, false>(rgba, pixels, out);
    else if (withAlpha)
        QuantisePixels<uint16_t, true>(rgba, pixels, out);
    else
        QuantisePixels<uint16_t, false>(rgba, pixels, out);
}

template <uint32_t MaxValue>
bool AllAlphaQuantiseTo(const float* HWY_RESTRICT rgba, size_t pixels) {
    const hn::ScalableTag<float> df;
    const hn::RebindToUnsigned<decltype(df)> du;
    const size_t lanes = hn::Lanes(df);
    // Without branches: the lowest sample of each lane, compared once at the end.
    auto lowest = hn::Set(du, MaxValue);
    auto lowerGroup = [&](const float* group) {
        hn::Vec<decltype(df)> r, g, b, a;
        hn::LoadInterleaved4(df, group, r, g, b, a);
        lowest = hn::Min(lowest, Quantise<MaxValue>(df, a));
    };
    size_t i = 0;
    for (; i + lanes <= pixels; i += lanes)
        lowerGroup(rgba + 4 * i);
    if (i < pixels) {
        // Padded with opaque pixels, which change nothing.
        alignas(kMaxLaneBytes) float tail[4 * kMaxGroupPixels];
        std::fill(std::begin(tail), std::end(tail), 1.0f);
        std::copy(rgba + 4 * i, rgba + 4 * pixels, tail);
        lowerGroup(tail);
    }
    return hn::AllTrue(du, hn::Eq(lowest, hn::Set(du, MaxValue)));
}

bool AllAlphaQuantiseToMax(const float* rgba, size_t pixels, int bitDepth) {
    return bitDepth == 8 ? AllAlphaQuantiseTo<255>(rgba, pixels)
                         : AllAlphaQuantiseTo<65535>(rgba, pixels);
}

void FilterPaethRow(const uint8_t* HWY_RESTRICT row, const uint8_t* HWY_RESTRICT previous,
                    size_t rowBytes, size_t bytesPerPixel, uint8_t* HWY_RESTRICT out) {
    // Bytes widened to 16-bit lanes, where a + b - 2c and the distances fit.
    const hn::ScalableTag<int16_t> d16;
    const hn::Rebind<uint8_t, decltype(d16)> d8;
    const size_t lanes = hn::Lanes(d16);
    // The first pixel has a = c = 0, so its prediction is b.
    const size_t leftEdge = std::min(bytesPerPixel, rowBytes);
    for (size_t i = 0; i < leftEdge; ++i)
        out[i] = uint8_t(row[i] - previous[i]);
    // A row of at most one pixel is done (and the loads below would start before it).
    if (leftEdge == rowBytes) return;
    // Bytes [i, i + lanes) of a row at `r` above `p` into `o`.
    auto filterAt = [&](const uint8_t* r, const uint8_t* p, uint8_t* o, size_t i) {
        const auto a = hn::PromoteTo(d16, hn::LoadU(d8, r + i - bytesPerPixel));
        const auto b = hn::PromoteTo(d16, hn::LoadU(d8, p + i));
        const auto c = hn::PromoteTo(d16, hn::LoadU(d8, p + i - bytesPerPixel));
        const auto distanceA = hn::Abs(hn::Sub(b, c));
        const auto distanceB = hn::Abs(hn::Sub(a, c));
        const auto distanceC = hn::Abs(hn::Sub(hn::Add(a, b), hn::Add(c, c)));
        // a unless another is strictly nearer; then b unless c is strictly nearer.
        const auto aLoses = hn::Or(distanceA > distanceB, distanceA > distanceC);
        const auto predicted =
            hn::IfThenElse(aLoses, hn::IfThenElse(distanceB > distanceC, c, b), a);
        hn::StoreU(hn::Sub(hn::LoadU(d8, r + i), hn::DemoteTo(d8, predicted)), d8, o + i);
    };
    if (rowBytes < leftEdge + lanes) {
        // Too short for a vector: one through zero-padded copies (only tiny images).
        alignas(kMaxLaneBytes) uint8_t rowCopy[2 * kMaxLaneBytes] = {};
        alignas(kMaxLaneBytes) uint8_t previousCopy[2 * kMaxLaneBytes] = {};
        alignas(kMaxLaneBytes) uint8_t outCopy[2 * kMaxLaneBytes];
        std::copy(row, row + rowBytes, rowCopy);
        std::copy(previous, previous + rowBytes, previousCopy);
        filterAt(rowCopy, previousCopy, outCopy, leftEdge);
        std::copy(outCopy + leftEdge, outCopy + rowBytes, out + leftEdge);
        return;
    }
    // Every output byte depends on the unfiltered rows alone, so the last vector may overlap
    // the one before it: it writes the same bytes again.
    size_t i = leftEdge;
    for (; i + lanes <= rowBytes; i += lanes)
        filterAt(row, previous, out, i);
    if (i < rowBytes) filterAt(row, previous, out, rowBytes - lanes);
}

uint32_t Adler32Update(uint32_t adler, const uint8_t* HWY_RESTRICT bytes, size_t size) {
    // s1 is 1 plus the sum of the bytes, s2 the sum of s1 after each byte, both modulo kBase.
    constexpr uint64_t kBase = 65521;
    // Chunks per block, small enough that no 32-bit lane or sum of lanes below overflows with
    // vectors of up to kMaxLaneBytes (32 lanes of 16 bits).
    constexpr size_t kBlockChunks = 256;
    uint64_t s1 = adler & 0xffff, s2 = adler >> 16;
    // A chunk is a vector of bytes widened to 16-bit lanes, multiplied and summed in pairs
    // into 32-bit lanes.
    const hn::ScalableTag<int16_t> d16;
    const hn::Rebind<uint8_t, decltype(d16)> d8;
    const hn::RepartitionToWide<decltype(d16)> d32;
    const size_t lanes = hn::Lanes(d16);
    const auto ones = hn::Set(d16, 1);
    // Byte j of a chunk is in s2 once for every byte from j to the chunk's end: lanes - j times.
    const auto weights = hn::Sub(hn::Set(d16, int16_t(lanes)), hn::Iota(d16, 0));
    auto sumOfLanes = [&](hn::Vec<decltype(d32)> v) {
        return uint64_t(hn::GetLane(hn::SumOfLanes(d32, v)));
    };
    size_t i = 0;
    while (size - i >= lanes) {
        const size_t chunks = std::min((size - i) / lanes, kBlockChunks);
        // The bytes' sum, the sum of that sum before each chunk, and the weighted sum; each
        // in two accumulators, as the second may take part of the pairs on some targets.
        auto sum = hn::Zero(d32), sumBefore = hn::Zero(d32), weighted = hn::Zero(d32);
        auto sumRest = hn::Zero(d32), weightedRest = hn::Zero(d32);
        for (size_t chunk = 0; chunk < chunks; ++chunk, i += lanes) {
            const auto x = hn::PromoteTo(d16, hn::LoadU(d8, bytes + i));
            sumBefore = hn::Add(sumBefore, hn::Add(sum, sumRest));
            sum = hn::ReorderWidenMulAccumulate(d32, x, ones, sum, sumRest);
            weighted = hn::ReorderWidenMulAccumulate(d32, x, weights, weighted, weightedRest);
        }
        // Each byte of the block adds the s1 before it to s2: the block's starting s1, the
        // bytes of the chunks before its own (`lanes` times per chunk) and its own chunk's.
        s2 += chunks * lanes * s1 + lanes * sumOfLanes(sumBefore) +
              sumOfLanes(hn::Add(weighted, weightedRest));
        s1 += sumOfLanes(hn::Add(sum, sumRest));
        s1 %= kBase;
        s2 %= kBase;
    }
    for (; i < size; ++i) {  // fewer bytes than a chunk
        s1 += bytes[i];
        s2 += s1;
    }
    return uint32_t((s2 % kBase) << 16 | (s1 % kBase));
}

}  // namespace HWY_NAMESPACE
}  // namespace quaternia
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace quaternia {

HWY_EXPORT(QuantisePngSamples);
HWY_EXPORT(AllAlphaQuantiseToMax);
HWY_EXPORT(FilterPaethRow);
HWY_EXPORT(Adler32Update);

void quantisePngSamples(const float* rgba, size_t pixels, int bitDepth, bool withAlpha,
                        uint8_t* out) {
    HWY_DYNAMIC_DISPATCH(QuantisePngSamples)(rgba, pixels, bitDepth, withAlpha, out);
}
bool allAlphaQuantiseToMax(const float* rgba, size_t pixels, int bitDepth) {
    return HWY_DYNAMIC_DISPATCH(AllAlphaQuantiseToMax)(rgba, pixels, bitDepth);
}
void filterPaethRow(const uint8_t* row, const uint8_t* previous, size_t rowBytes,
                    size_t bytesPerPixel, uint8_t* out) {
    HWY_DYNAMIC_DISPATCH(FilterPaethRow)(row, previous, rowBytes, bytesPerPixel, out);
}

uint32_t adler32Update(uint32_t adler, const uint8_t* bytes, size_t size) {
    return HWY_DYNAMIC_DISPATCH(Adler32Update)(adler, bytes, size);
}

}  // namespace quaternia
#endif  // HWY_ONCE
