// The environment's diffuse light (environment.h): an irradiance map for the unoccluded light,
// and shadow rays, drawn half from the cosine and half from the map's light, whose visibility
// scales it. Estimating only the occluded fraction (a ratio of the rays' weighted visibility)
// keeps a point that sees the whole environment exact and noiseless, and the noise where the
// set hides part of it falls with render.samples; a sun or a soft box gets the rays it needs
// from the map's distribution (Pharr, Jakob and Humphreys, Physically Based Rendering, 4th ed.,
// section 12.5, infinite area lights; the balance heuristic of Veach and Guibas 1995).
#include <algorithm>
#include <cmath>
#include <cstring>

#include "quaternia/render/environment.h"
#include "quaternia/render/sample_pattern.h"

namespace quaternia {
namespace {

constexpr int kIrradianceWidth = 32;    // the irradiance map (it varies slowly: a cosine lobe)
constexpr int kIrradianceSource = 64;   // the widest level it is convolved from
constexpr int kDistributionWidth = 64;  // the widest level the shadow rays are drawn from
constexpr double kGolden = 0.6180339887498949;

double wrap01(double u) {
    return u - std::floor(u);
}

double luminance(const Color& c) {
    return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

// The solid angle of row y of a latitude-longitude map of `height` rows and `width` columns:
// (2 pi / width) (cos theta0 - cos theta1), exact, so that the texels sum to 4 pi.
double texelSolidAngle(int y, int width, int height) {
    const double theta0 = M_PI * y / height, theta1 = M_PI * (y + 1) / height;
    return 2 * M_PI / width * (std::cos(theta0) - std::cos(theta1));
}

}  // namespace

void Environment::buildIrradiance() {
    // The widest level no wider than kIrradianceSource.
    size_t source = 0;
    while (source + 1 < levels_.size() && levels_[source].width > kIrradianceSource)
        ++source;
    const Level& level = levels_[source];
    std::vector<Vector3d> directions;
    std::vector<double> solidAngles;
    std::vector<Color> radiances;
    for (int y = 0; y < level.height; ++y)
        for (int x = 0; x < level.width; ++x) {
            directions.push_back(fromMap((x + 0.5) / level.width, (y + 0.5) / level.height));
            solidAngles.push_back(texelSolidAngle(y, level.width, level.height));
            radiances.push_back(level.texel(x, y));
        }
    irradiance_.width = kIrradianceWidth;
    irradiance_.height = kIrradianceWidth / 2;
    irradiance_.rgb.resize(3 * size_t(irradiance_.width) * size_t(irradiance_.height));
    for (int oy = 0; oy < irradiance_.height; ++oy)
        for (int ox = 0; ox < irradiance_.width; ++ox) {
            const Vector3d n =
                fromMap((ox + 0.5) / irradiance_.width, (oy + 0.5) / irradiance_.height);
            // The cosine-weighted mean radiance over the hemisphere about n: E(n) / pi. Dividing
            // by the discrete sum of the weights (pi in the limit) makes a constant map exact.
            Color sum;
            double weights = 0;
            for (size_t t = 0; t < directions.size(); ++t) {
                const double c = dot(n, directions[t]);
                if (!(c > 0)) continue;
                const double w = c * solidAngles[t];
                sum += radiances[t] * w;
                weights += w;
            }
            const Color mean = weights > 0 ? sum / weights : Color();
            float* out =
                &irradiance_.rgb[3 * (size_t(oy) * size_t(irradiance_.width) + size_t(ox))];
            out[0] = float(mean.x), out[1] = float(mean.y), out[2] = float(mean.z);
        }
}

void Environment::buildDistribution() {
    size_t source = 0;
    while (source + 1 < levels_.size() && levels_[source].width > kDistributionWidth)
        ++source;
    const Level& level = levels_[source];
    const int w = distributionWidth_ = level.width, h = distributionHeight_ = level.height;
    rowCdf_.assign(size_t(h) + 1, 0.0);
    texelCdf_.assign(size_t(h) * size_t(w + 1), 0.0);
    texelPdf_.assign(size_t(h) * size_t(w), 0.0);
    std::vector<double> power(size_t(w) * size_t(h));
    double total = 0;
    for (int y = 0; y < h; ++y) {
        const double omega = texelSolidAngle(y, w, h);
        double row = 0;
        for (int x = 0; x < w; ++x) {
            const double p = luminance(level.texel(x, y)) * omega;
            power[size_t(y) * size_t(w) + size_t(x)] = p;
            row += p;
            texelCdf_[size_t(y) * size_t(w + 1) + size_t(x) + 1] = row;
        }
        for (int x = 1; x <= w; ++x)
            texelCdf_[size_t(y) * size_t(w + 1) + size_t(x)] /= row > 0 ? row : 1;
        rowCdf_[size_t(y) + 1] = rowCdf_[size_t(y)] + row;
        total += row;
    }
    power_ = total;
    if (!(total > 0)) {  // a black map: no light to shadow, no rays (their weights are 0)
        rowCdf_.clear();
        return;
    }
    for (double& c : rowCdf_)
        c /= total;
    for (int y = 0; y < h; ++y) {
        const double omega = texelSolidAngle(y, w, h);
        for (int x = 0; x < w; ++x)
            texelPdf_[size_t(y) * size_t(w) + size_t(x)] =
                power[size_t(y) * size_t(w) + size_t(x)] / total / omega;
    }
}

double Environment::mapPdf(const Vector3d& d) const {
    if (rowCdf_.empty()) return 0;
    double u, v;
    toMap(d, u, v);
    const int x = std::min(int(u * distributionWidth_), distributionWidth_ - 1);
    const int y = std::min(int(v * distributionHeight_), distributionHeight_ - 1);
    return texelPdf_[size_t(y) * size_t(distributionWidth_) + size_t(x)];
}

Color Environment::diffuse(const Vector3d& n) const {
    double u, v;
    toMap(n, u, v);
    return irradiance_.bilinear(u, v);
}

void Environment::shadowDirections(uint32_t seed, const Vector3d& n,
                                   std::span<EnvironmentDirection> out) const {
    const int count = int(out.size());
    if (count == 0) return;
    const int mapRays = rowCdf_.empty() ? 0 : count / 2;
    const int cosineRays = count - mapRays;
    const double cosineShare = double(cosineRays) / count;
    // Each strategy's points: a rank-1 lattice of its count, turned by offsets hashed from the
    // seed (Cranley-Patterson rotation), so a point's rays cover their domain evenly.
    const double r1 = hashUnit(seed, 1, 0), r2 = hashUnit(seed, 2, 0);
    const double r3 = hashUnit(seed, 3, 0), r4 = hashUnit(seed, 4, 0);
    // A frame about n for the cosine's directions.
    const Vector3d a = std::abs(n.x) < 0.9 ? Vector3d(1, 0, 0) : Vector3d(0, 1, 0);
    const Vector3d t = normalize(cross(n, a)), b = cross(n, t);
    for (int k = 0; k < count; ++k) {
        Vector3d d;
        if (k < cosineRays) {
            const double u = (k + r1) / cosineRays, v = wrap01(k * kGolden + r2);
            const double r = std::sqrt(u), phi = 2 * M_PI * v;
            d = t * (r * std::cos(phi)) + b * (r * std::sin(phi)) + n * std::sqrt(1 - u);
        } else {
            const int j = k - cosineRays;
            const double u1 = (j + r3) / mapRays, u2 = wrap01(j * kGolden + r4);
            // The row, then the column, by their cumulative shares; the rest of each number
            // places the direction within the texel, uniform in solid angle.
            const int h = distributionHeight_, w = distributionWidth_;
            int y = int(std::upper_bound(rowCdf_.begin(), rowCdf_.end(), u1) - rowCdf_.begin()) - 1;
            y = std::clamp(y, 0, h - 1);
            const double rowShare = rowCdf_[size_t(y) + 1] - rowCdf_[size_t(y)];
            const double inRow = rowShare > 0 ? (u1 - rowCdf_[size_t(y)]) / rowShare : 0.5;
            const double* cdf = &texelCdf_[size_t(y) * size_t(w + 1)];
            int x = int(std::upper_bound(cdf, cdf + w + 1, u2) - cdf) - 1;
            x = std::clamp(x, 0, w - 1);
            const double share = cdf[x + 1] - cdf[x];
            const double inTexel = share > 0 ? (u2 - cdf[x]) / share : 0.5;
            const double cos0 = std::cos(M_PI * y / h), cos1 = std::cos(M_PI * (y + 1) / h);
            const double cosTheta = cos0 + (cos1 - cos0) * std::clamp(inRow, 0.0, 1.0);
            d = fromMap((x + std::clamp(inTexel, 0.0, 1.0)) / w, std::acos(cosTheta) / M_PI);
        }
        const double c = dot(n, d);
        double weight = 0;
        if (c > 0) {
            // The light carried (the texel's luminance: the map's pdf times its power) times
            // the cosine, over the pdf of the mix of both strategies (per steradian).
            const double mapDensity = mapPdf(d);
            const double pdf = cosineShare * c / M_PI + (1 - cosineShare) * mapDensity;
            const double light = mapDensity * power_;
            weight = pdf > 0 ? light * c / pdf : 0;
        }
        out[size_t(k)] = {normalize(d), weight};
    }
}

double Environment::openFraction(std::span<const EnvironmentDirection> directions,
                                 std::span<const double> visibility) {
    double open = 0, all = 0;
    for (size_t k = 0; k < directions.size(); ++k) {
        open += directions[k].weight * visibility[k];
        all += directions[k].weight;
    }
    return all > 0 ? open / all : 1.0;
}

uint32_t Environment::seedOf(const Point3d& p) {
    const float x = float(p.x), y = float(p.y), z = float(p.z);
    uint32_t bx, by, bz;
    std::memcpy(&bx, &x, 4);
    std::memcpy(&by, &y, 4);
    std::memcpy(&bz, &z, 4);
    return uint32_t(hashUnit(bx, by, bz) * 4294967296.0);
}

}  // namespace quaternia
