// Reading the environment's map where many rays leave the scene (environment.h): a camera row's
// background, a wave's escaping rays. The angles come from a polynomial arctangent in float
// (error about 1e-5 radians, far below a texel) in loops the compiler vectorises, then the
// bilinear reads; radiance() takes the same angles for a single ray, so all read alike.
#include <algorithm>
#include <cmath>

#include "quaternia/render/environment.h"

namespace quaternia {
namespace {

// atan2(y, x) in float without branches: the arctangent's odd minimax polynomial on [0, 1]
// (Abramowitz and Stegun 4.4.49's form, error about 1e-5 radians), then the octant by
// arithmetic selects rather than branches (random directions would mispredict them).
inline float fastAtan2(float y, float x) {
    const float ax = std::fabs(x), ay = std::fabs(y);
    const float big = std::max(ax, ay), small = std::min(ax, ay);
    const float a = small / std::max(big, 1e-30f);
    const float s = a * a;
    float r =
        a * (0.99997726f +
             s * (-0.33262347f +
                  s * (0.19354346f + s * (-0.11643287f + s * (0.05265332f - 0.01172120f * s)))));
    const float swapped = ay > ax ? 1.0f : 0.0f;
    r += swapped * (1.57079633f - 2 * r);
    const float behind = x < 0 ? 1.0f : 0.0f;
    r += behind * (3.14159265f - 2 * r);
    return std::copysign(r, y);
}

}  // namespace

void Environment::toMap(const Vector3d& d, double& u, double& v) const {
    const float e = float(dot(d, east_)), c = float(dot(d, centre_)), h = float(dot(d, up_));
    u = std::clamp(0.5 + fastAtan2(e, c) * (0.5 / M_PI), 0.0, 1.0);
    v = std::clamp(fastAtan2(std::sqrt(e * e + c * c), h) * (1 / M_PI), 0.0, 1.0);
}

// Compiled twice, picked at load time by the CPU (GCC's function multi-versioning): 8 lanes of
// AVX2 where the machine has it, 4 of SSE2 otherwise. A row of the background or a wave's
// escaping rays is then a small part of a frame.
__attribute__((target_clones("avx2", "default"))) void Environment::lookUp(
    const Level& level, int n, const float* e, const float* c, const float* h, const float* sun,
    float* rgb) const {
    const int width = level.width, height = level.height;
    // Pass 1, vectorised: each ray's four texels (as offsets into the level) and weights.
    int row0[kLookUpChunk], row1[kLookUpChunk], column0[kLookUpChunk], column1[kLookUpChunk];
    float fx[kLookUpChunk], fy[kLookUpChunk], inSun[kLookUpChunk];
    const float sunCosine = sun_ && sun != nullptr ? float(sunCosine_) : 2.0f;
    // Over the whole chunk (a fixed count the compiler vectorises without a remainder loop);
    // the callers' arrays are full chunks, the entries past n read and never used.
    for (int i = 0; i < kLookUpChunk; ++i) {
        const float horizontal = std::sqrt(e[i] * e[i] + c[i] * c[i]);
        const float u = 0.5f + fastAtan2(e[i], c[i]) * float(0.5 / M_PI);
        const float v = fastAtan2(horizontal, h[i]) * float(1 / M_PI);
        // x, y >= -0.5: truncating x + 1 floors it (no SSE4 floor in the baseline build).
        const float x = std::clamp(u, 0.0f, 1.0f) * float(width) - 0.5f;
        const float y = std::clamp(v, 0.0f, 1.0f) * float(height) - 0.5f;
        const int ix = int(x + 1.0f) - 1, iy = int(y + 1.0f) - 1;
        fx[i] = x - float(ix), fy[i] = y - float(iy);
        // Columns wrap around the map, rows stop at the poles.
        const int x0 = ix < 0 ? ix + width : ix;
        const int x1 = ix + 1 >= width ? ix + 1 - width : ix + 1;
        column0[i] = 3 * x0, column1[i] = 3 * x1;
        row0[i] = 3 * width * std::max(iy, 0);
        row1[i] = 3 * width * std::min(iy + 1, height - 1);
        const float length = std::sqrt(horizontal * horizontal + h[i] * h[i]);
        inSun[i] = (sun != nullptr ? sun[i] : 0.0f) >= sunCosine * length ? 1.0f : 0.0f;
    }
    const float* texels = level.rgb.data();
    const float sunRed = float(sunRadiance_.x), sunGreen = float(sunRadiance_.y),
                sunBlue = float(sunRadiance_.z);
    for (int i = 0; i < n; ++i) {
        const float* a = texels + row0[i] + column0[i];
        const float* b = texels + row0[i] + column1[i];
        const float* p = texels + row1[i] + column0[i];
        const float* q = texels + row1[i] + column1[i];
        const float w00 = (1 - fx[i]) * (1 - fy[i]), w10 = fx[i] * (1 - fy[i]),
                    w01 = (1 - fx[i]) * fy[i], w11 = fx[i] * fy[i];
        rgb[3 * i] = a[0] * w00 + b[0] * w10 + p[0] * w01 + q[0] * w11 + inSun[i] * sunRed;
        rgb[3 * i + 1] = a[1] * w00 + b[1] * w10 + p[1] * w01 + q[1] * w11 + inSun[i] * sunGreen;
        rgb[3 * i + 2] = a[2] * w00 + b[2] * w10 + p[2] * w01 + q[2] * w11 + inSun[i] * sunBlue;
    }
}

void Environment::radianceRow(const Vector3d& first, const Vector3d& step, int x0, int count,
                              float alpha, Rgba* out) const {
    // Each direction's components along the map's frame, linear in the pixel's index.
    const Vector3d sunAxis = sun_ ? sunDirection_ : Vector3d();
    const float e0 = float(dot(first, east_)), e1 = float(dot(step, east_));
    const float c0 = float(dot(first, centre_)), c1 = float(dot(step, centre_));
    const float h0 = float(dot(first, up_)), h1 = float(dot(step, up_));
    const float s0 = float(dot(first, sunAxis)), s1 = float(dot(step, sunAxis));
    float e[kLookUpChunk] = {}, c[kLookUpChunk] = {}, h[kLookUpChunk] = {}, s[kLookUpChunk] = {};
    float rgb[3 * kLookUpChunk];
    for (int start = 0; start < count; start += kLookUpChunk) {
        const int n = std::min(kLookUpChunk, count - start);
        for (int i = 0; i < n; ++i) {
            const float p = float(x0 + start + i);
            e[i] = e0 + p * e1, c[i] = c0 + p * c1, h[i] = h0 + p * h1, s[i] = s0 + p * s1;
        }
        lookUp(levels_.front(), n, e, c, h, s, rgb);
        for (int i = 0; i < n; ++i)
            out[start + i] = Rgba{rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2], alpha};
    }
}

void Environment::lookUpDirections(const Level& level, bool withSun,
                                   std::span<const Vector3d> directions,
                                   std::span<Color> out) const {
    const Vector3d sunAxis = sun_ ? sunDirection_ : Vector3d();
    float e[kLookUpChunk] = {}, c[kLookUpChunk] = {}, h[kLookUpChunk] = {}, s[kLookUpChunk] = {};
    float rgb[3 * kLookUpChunk];
    const int count = int(directions.size());
    for (int start = 0; start < count; start += kLookUpChunk) {
        const int n = std::min(kLookUpChunk, count - start);
        for (int i = 0; i < n; ++i) {
            const Vector3d& d = directions[size_t(start + i)];
            e[i] = float(dot(d, east_)), c[i] = float(dot(d, centre_)), h[i] = float(dot(d, up_));
            s[i] = float(dot(d, sunAxis));
        }
        lookUp(level, n, e, c, h, withSun ? s : nullptr, rgb);
        for (int i = 0; i < n; ++i)
            out[size_t(start + i)] = Color(rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]);
    }
}

void Environment::radianceBatch(std::span<const Vector3d> directions,
                                std::span<const double> spreads, std::span<Color> out) const {
    lookUpDirections(levels_.front(), true, directions, out);
    // Blurred rays read between two levels (radiance()).
    const double texelAngle = 2 * M_PI / levels_.front().width;
    for (size_t j = 0; j < directions.size(); ++j)
        if (spreads[j] > texelAngle) out[j] = radiance(directions[j], spreads[j]);
}

void Environment::diffuseBatch(std::span<const Vector3d> normals, std::span<Color> out) const {
    lookUpDirections(irradiance_, false, normals, out);
}

}  // namespace quaternia
