#include "quaternia/render/environment.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <stdexcept>
#include <utility>

#include <sys/stat.h>

#include "quaternia/util/error.h"

namespace quaternia {
namespace {

// The pyramid stops at this width: coarser levels blur more than any roughness asks for.
constexpr int kSmallestLevel = 8;

// A file name as one line of an error message.
std::string oneLine(std::string name) {
    for (char& c : name)
        if (c == '\n' || c == '\r') c = '?';
    return name;
}

}  // namespace

Color Environment::Level::texel(int x, int y) const {
    x = ((x % width) + width) % width;
    y = std::clamp(y, 0, height - 1);
    const float* p = &rgb[3 * (size_t(y) * size_t(width) + size_t(x))];
    return Color(p[0], p[1], p[2]);
}

Color Environment::Level::bilinear(double u, double v) const {
    const double x = u * width - 0.5, y = v * height - 0.5;
    const double fx = std::floor(x), fy = std::floor(y);
    const double ax = x - fx, ay = y - fy;
    // Columns wrap around the map; rows stop at the poles.
    int x0 = int(fx), x1 = x0 + 1;
    if (x0 < 0) x0 += width;
    if (x1 >= width) x1 -= width;
    x0 = std::clamp(x0, 0, width - 1), x1 = std::clamp(x1, 0, width - 1);
    const int y0 = std::clamp(int(fy), 0, height - 1), y1 = std::clamp(int(fy) + 1, 0, height - 1);
    const float* row0 = &rgb[3 * size_t(y0) * size_t(width)];
    const float* row1 = &rgb[3 * size_t(y1) * size_t(width)];
    const double w00 = (1 - ax) * (1 - ay), w10 = ax * (1 - ay), w01 = (1 - ax) * ay, w11 = ax * ay;
    Color c;
    for (int k = 0; k < 3; ++k)
        c[k] = row0[3 * x0 + k] * w00 + row0[3 * x1 + k] * w10 + row1[3 * x0 + k] * w01 +
               row1[3 * x1 + k] * w11;
    return c;
}

Environment::Environment(const EnvironmentSettings& settings, const Vector3d& up, HdrImage map)
    : settings_(settings) {
    up_ = normalize(up);
    // The map's centre: the world's -z made perpendicular to up (+x where up is along z),
    // then turned about up by the rotation (Rodrigues' formula in the plane).
    Vector3d centre = Vector3d(0, 0, -1) - up_ * dot(Vector3d(0, 0, -1), up_);
    if (length(centre) < 1e-6) centre = Vector3d(1, 0, 0) - up_ * dot(Vector3d(1, 0, 0), up_);
    centre = normalize(centre);
    const double angle = settings.rotation * M_PI / 180;
    centre_ = centre * std::cos(angle) + cross(up_, centre) * std::sin(angle);
    east_ = cross(centre_, up_);
    if (map.width == 0) {
        map = builtinMap(settings, settings.builtin == EnvironmentBuiltin::Studio ? 512 : 256);
    } else if (map.rgb.size() != 3 * size_t(map.width) * size_t(std::max(map.height, 0))) {
        throw std::invalid_argument("Environment: the map's pixels are not width x height");
    } else if (map.width != 2 * map.height) {
        throw UserError("environment.map",
                        "environment.map: '" + oneLine(settings.map) + "' is " +
                            std::to_string(map.width) + " x " + std::to_string(map.height) +
                            " pixels; a latitude-longitude map is twice as wide as high");
    }
    for (float& value : map.rgb)
        value = float(value * settings.intensity);
    buildPyramid(std::move(map));
    if (settings.map.empty() && settings.builtin == EnvironmentBuiltin::Sky &&
        settings.sunIntensity > 0) {
        LightSettings sun;
        sun.enabled = true;
        sun.kind = LightKind::Directional;
        sun.direction = settings.sunDirection;
        sun.color = settings.sunColor;
        sun.intensity = settings.sunIntensity;
        sun.shadows = Shadows::Soft;
        sun.angularRadius = settings.sunSize;
        sun_ = sun;
        sunDirection_ = normalize(settings.sunDirection);
        const double radius = settings.sunSize * M_PI / 180;
        sunCosine_ = std::cos(radius);
        // A disc of uniform radiance L and angular radius a gives irradiance L pi sin^2 a at
        // normal incidence: the disc's radiance that makes the light's irradiance.
        const double sine = std::sin(radius);
        sunRadiance_ = settings.sunColor * (settings.sunIntensity / (M_PI * sine * sine));
    }
    buildIrradiance();
    buildDistribution();
}

Vector3d Environment::fromMap(double u, double v) const {
    const double theta = v * M_PI, phi = (u - 0.5) * 2 * M_PI;
    const double s = std::sin(theta);
    return up_ * std::cos(theta) + (centre_ * std::cos(phi) + east_ * std::sin(phi)) * s;
}

void Environment::buildPyramid(HdrImage image) {
    Level level{image.width, image.height, std::move(image.rgb)};
    levels_.push_back(std::move(level));
    while (levels_.back().width > kSmallestLevel && levels_.back().height > 1) {
        const Level& fine = levels_.back();
        Level coarse{fine.width / 2, fine.height / 2, {}};
        coarse.rgb.resize(3 * size_t(coarse.width) * size_t(coarse.height));
        for (int y = 0; y < coarse.height; ++y)
            for (int x = 0; x < coarse.width; ++x) {
                const Color sum = fine.texel(2 * x, 2 * y) + fine.texel(2 * x + 1, 2 * y) +
                                  fine.texel(2 * x, 2 * y + 1) + fine.texel(2 * x + 1, 2 * y + 1);
                float* out = &coarse.rgb[3 * (size_t(y) * size_t(coarse.width) + size_t(x))];
                out[0] = float(sum.x / 4), out[1] = float(sum.y / 4), out[2] = float(sum.z / 4);
            }
        levels_.push_back(std::move(coarse));
    }
}

Color Environment::radiance(const Vector3d& d, double spread) const {
    double u, v;
    toMap(d, u, v);
    Color c;
    // The level whose texels span about `spread`, interpolated between the two nearest.
    const double texelAngle = 2 * M_PI / levels_.front().width;
    const double lod = spread > texelAngle ? std::log2(spread / texelAngle) : 0.0;
    const int last = int(levels_.size()) - 1;
    if (lod <= 0) {
        c = levels_.front().bilinear(u, v);
    } else if (lod >= last) {
        c = levels_.back().bilinear(u, v);
    } else {
        const int lower = int(lod);
        const double f = lod - lower;
        c = levels_[size_t(lower)].bilinear(u, v) * (1 - f) +
            levels_[size_t(lower) + 1].bilinear(u, v) * f;
    }
    if (sun_) {
        // The disc, spread over a cone of `spread` radians where that is wider (the same
        // power: radiance times solid angle).
        const double cone = std::cos(spread);
        if (cone < sunCosine_) {
            if (dot(d, sunDirection_) >= cone) c += sunRadiance_ * ((1 - sunCosine_) / (1 - cone));
        } else if (dot(d, sunDirection_) >= sunCosine_) {
            c += sunRadiance_;
        }
    }
    return c;
}

std::shared_ptr<const Environment> environmentOf(const Scene& scene, const MemoryBudget& budget) {
    const EnvironmentSettings& settings = scene.environment;
    if (!settings.enabled) return nullptr;
    // The last environment made, kept for the next scene that asks for the same one (a film's
    // frames, the explorer's edits, a notebook's renders): reading a large map and filtering it
    // take longer than a preview.
    static std::mutex mutex;
    static EnvironmentSettings cachedSettings;
    static Vector3d cachedUp;
    static std::pair<int64_t, int64_t> cachedFile;  // the map's modification time and size
    static std::shared_ptr<const Environment> cached;
    // A map rewritten under the same name is read again.
    std::pair<int64_t, int64_t> file{0, 0};
    struct stat status;
    if (!settings.map.empty() && ::stat(settings.map.c_str(), &status) == 0)
        file = {int64_t(status.st_mtim.tv_sec) * 1000000000 + status.st_mtim.tv_nsec,
                int64_t(status.st_size)};
    std::lock_guard lock(mutex);
    if (cached && cachedSettings == settings && cachedUp == scene.camera.up && cachedFile == file)
        return cached;
    HdrImage map;
    if (!settings.map.empty()) {
        map = readHdrImage(settings.map, "environment.map", budget);
        // The pyramid and the filtered levels take about a third more.
        requireMemory(uint64_t(map.rgb.size()) * sizeof(float) * 2, budget, "environment.map",
                      "environment.map: the map '" + oneLine(settings.map) + "'",
                      "use a smaller map or raise --memory-budget");
    }
    cached = std::make_shared<const Environment>(settings, scene.camera.up, std::move(map));
    cachedSettings = settings;
    cachedUp = scene.camera.up;
    cachedFile = file;
    return cached;
}

}  // namespace quaternia
