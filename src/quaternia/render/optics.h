// Geometric optics at a surface: mirror reflection, refraction by Snell's law, the exact
// Fresnel reflectance of a dielectric and Schlick's approximation of it (Schlick 1994), which
// the reflective material and the ground use with their reflectivity as reflectance at normal
// incidence. Directions are unit vectors; `normal` faces the side the ray comes from.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "quaternia/algebra/vecmath.h"

namespace quaternia {

// d reflected about the plane of normal n: d - 2 (d.n) n.
inline Vector3d reflect(const Vector3d& d, const Vector3d& n) {
    return d - n * (2 * dot(d, n));
}

// d refracted from a medium of index n1 into one of index n2 through a surface whose normal n
// faces the incoming side (d.n < 0): n1 sin(i) = n2 sin(t). Nothing where sin(t) would exceed 1
// (total internal reflection).
inline std::optional<Vector3d> refract(const Vector3d& d, const Vector3d& n, double n1, double n2) {
    const double eta = n1 / n2;
    const double cosI = -dot(d, n);
    const double sin2T = eta * eta * std::max(0.0, 1 - cosI * cosI);
    if (sin2T > 1) return std::nullopt;
    const double cosT = std::sqrt(1 - sin2T);
    return normalize(d * eta + n * (eta * cosI - cosT));
}

// The reflectance of unpolarised light at a smooth dielectric boundary from index n1 into n2,
// cosI the cosine of the angle of incidence: the mean of the s and p Fresnel equations; 1 under
// total internal reflection.
inline double fresnelDielectric(double cosI, double n1, double n2) {
    cosI = std::clamp(cosI, 0.0, 1.0);
    const double sin2T = (n1 / n2) * (n1 / n2) * (1 - cosI * cosI);
    if (sin2T >= 1) return 1;
    const double cosT = std::sqrt(1 - sin2T);
    const double rs = (n1 * cosI - n2 * cosT) / (n1 * cosI + n2 * cosT);
    const double rp = (n1 * cosT - n2 * cosI) / (n1 * cosT + n2 * cosI);
    return 0.5 * (rs * rs + rp * rp);
}

// Schlick's approximation: r0 at normal incidence, rising to 1 at grazing incidence.
inline double fresnelSchlick(double cosI, double r0) {
    const double m = 1 - std::clamp(cosI, 0.0, 1.0);
    const double m2 = m * m;
    return r0 + (1 - r0) * m2 * m2 * m;
}

}  // namespace quaternia
