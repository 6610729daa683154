// The built-in environments (environment.h), so that a look needs no file: a sky of three
// colours (its sun is a light, Environment::sun) and a photographer's studio, soft boxes over a
// dark floor, the light a mirror-polished object needs to read as metal. data/environments/
// studio.hdr is this studio written by `quaternia environment` (docs/lighting.md).
#include <algorithm>
#include <cmath>

#include "quaternia/render/environment.h"

namespace quaternia {
namespace {

double smoothstep(double a, double b, double v) {
    const double t = std::clamp((v - a) / (b - a), 0.0, 1.0);
    return t * t * (3 - 2 * t);
}

// A rectangular soft box seen from the centre: its axis, its half-sizes in degrees across
// (about the world's up) and along, and its radiance. The edges fade over kSoftEdge degrees.
struct SoftBox {
    Vector3d axis;
    double halfWidth, halfHeight;
    double radiance;
};
constexpr double kSoftEdge = 3;

double softBoxLight(const SoftBox& box, const Vector3d& d) {
    const Vector3d axis = normalize(box.axis);
    const double along = dot(d, axis);
    // Beyond the box's corner (its half-diagonal, in degrees, bounds both angles): dark.
    const double corner = std::hypot(box.halfWidth, box.halfHeight) * M_PI / 180;
    if (!(along > std::cos(std::min(corner, M_PI / 2)))) return 0;
    const Vector3d side =
        std::abs(axis.y) < 0.99 ? normalize(cross(axis, Vector3d(0, 1, 0))) : Vector3d(1, 0, 0);
    const Vector3d upward = cross(side, axis);
    const double across = std::atan2(dot(d, side), along) * 180 / M_PI;
    const double upwards = std::atan2(dot(d, upward), along) * 180 / M_PI;
    const double inside =
        (1 - smoothstep(box.halfWidth - kSoftEdge, box.halfWidth, std::abs(across))) *
        (1 - smoothstep(box.halfHeight - kSoftEdge, box.halfHeight, std::abs(upwards)));
    return box.radiance * inside;
}

Color studio(const Vector3d& d) {
    // A dark grey cyclorama: the floor below, walls brightening a little upwards.
    const double h = d.y;
    Color c = h < 0 ? Color(0.025, 0.025, 0.027)
                    : Color(0.04, 0.04, 0.045) + Color(0.05, 0.05, 0.055) * h;
    // A wide box overhead and in front, a tall strip to the left, a narrow rim strip behind
    // on the right: the three lights of a product photograph.
    static const SoftBox boxes[] = {
        {Vector3d(0.0, 0.85, -0.5), 28, 18, 5.0},
        {Vector3d(-0.95, 0.25, -0.25), 9, 32, 4.0},
        {Vector3d(0.85, 0.3, 0.45), 6, 28, 3.0},
    };
    for (const SoftBox& box : boxes)
        c += Color(1, 1, 1) * softBoxLight(box, d);
    return c;
}

Color sky(const EnvironmentSettings& s, const Vector3d& d) {
    const double h = d.y;
    if (h >= 0) {
        // From the horizon's colour to the sky's over the first few tens of degrees.
        const double t = std::sqrt(h);
        return s.horizonColor * (1 - t) + s.skyColor * t;
    }
    // The ground, with a narrow haze at the horizon.
    const double t = std::min(1.0, -h * 12);
    return (s.horizonColor * 0.5 + s.groundColor * 0.5) * (1 - t) + s.groundColor * t;
}

}  // namespace

Color builtinRadiance(const EnvironmentSettings& settings, const Vector3d& d) {
    return settings.builtin == EnvironmentBuiltin::Studio ? studio(d) : sky(settings, d);
}

HdrImage builtinMap(const EnvironmentSettings& settings, int width) {
    HdrImage image;
    image.width = width;
    image.height = width / 2;
    image.rgb.resize(3 * size_t(image.width) * size_t(image.height));
    // Texel centres in the map's own frame (y up, -z at the centre, +x to the east), as
    // Environment::fromMap places them before its rotation.
    for (int y = 0; y < image.height; ++y) {
        const double theta = M_PI * (y + 0.5) / image.height;
        for (int x = 0; x < image.width; ++x) {
            const double phi = 2 * M_PI * ((x + 0.5) / image.width - 0.5);
            const Vector3d d(std::sin(theta) * std::sin(phi), std::cos(theta),
                             -std::sin(theta) * std::cos(phi));
            const Color c = builtinRadiance(settings, d);
            float* out = &image.rgb[3 * (size_t(y) * size_t(image.width) + size_t(x))];
            out[0] = float(c.x), out[1] = float(c.y), out[2] = float(c.z);
        }
    }
    return image;
}

}  // namespace quaternia
