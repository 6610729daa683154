#include "quaternia/plane/plane_certificate.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <complex>
#include <memory>
#include <numbers>

#include "quaternia/fractal/algebra_rules.h"
#include "quaternia/image/plane_view.h"
#include "quaternia/interval/interval.h"
#include "quaternia/plane/plane_render.h"
#include "quaternia/util/error.h"
#include "quaternia/util/parallel.h"

namespace quaternia {
namespace {

using Complex = std::complex<double>;

// A bound of the rounding of a plane point (PlaneView::pointAt) and of its image in the
// algebra, relative to the largest term: each is a handful of operations, a few ulps (2^-52) of
// that term, so 2^-40 leaves a factor of 500 to spare.
constexpr double kRounding = 0x1p-40;
// A cell not proven missed whole is cut into four parts, and each part again, this many times.
constexpr int kSubdivisions = 4;

// The image-space square [x0, x0 + size] x [y0, y0 + size] (a pixel's is [px, px + 1] x
// [py, py + 1]).
struct Square {
    double x0, y0, size;
};

// Where the view's points lie, for the rounding margins: every plane point of the image is
// within this of 0 in each coordinate.
double viewReach(const PlaneView& view) {
    return std::max(std::abs(view.centre.real()), std::abs(view.centre.imag())) +
           view.width * (1.0 + double(view.pixelHeight) / double(view.pixelWidth));
}

// The unit turn of the view, as pointAt computes it; one pixel down the image moves a plane
// point by pixelSize (turn.imag, -turn.real).
Complex viewTurn(const PlaneView& view) {
    return std::polar(1.0, view.rotationDegrees * std::numbers::pi / 180);
}

// The plane of a set kind in its algebra: plane point (x, y) is origin + x u + y v; the
// `magnitude` fields bound the components' absolute terms (|origin| and |u|, |v| as sums of
// absolute values, where they were computed), for the rounding margin.
struct PlaneInAlgebra {
    Hypercomplex origin{}, u{}, v{};
    Hypercomplex originMagnitude{}, uMagnitude{}, vMagnitude{};

    Hypercomplex at(Complex z) const {
        Hypercomplex p{};
        for (size_t k = 0; k < p.size(); ++k)
            p[k] = origin[k] + z.real() * u[k] + z.imag() * v[k];
        return p;
    }
};

PlaneInAlgebra exactPlane(const Hypercomplex& origin, const Hypercomplex& u,
                          const Hypercomplex& v) {
    PlaneInAlgebra plane{origin, u, v, {}, {}, {}};
    for (size_t k = 0; k < origin.size(); ++k) {
        plane.originMagnitude[k] = std::abs(origin[k]);
        plane.uMagnitude[k] = std::abs(u[k]);
        plane.vMagnitude[k] = std::abs(v[k]);
    }
    return plane;
}

Hypercomplex hypercomplexOf(const Quaternion& q) {
    return {q.w, q.x, q.y, q.z, 0, 0, 0, 0};
}

// The plane of the 8-component algebras: plane.origin, plane.u and plane.v are points and
// directions of the 3D slice, whose isometry maps (x, y, z) to o + x t_0 + y t_1 + z t_2.
PlaneInAlgebra planeThroughSlice(const PlaneSettings& settings, const Slice& slice) {
    const Hypercomplex o = slice.fromWorld(Point3d(0, 0, 0));
    const auto& t = slice.tangents();
    PlaneInAlgebra plane;
    auto apply = [&](const Quaternion& q, Hypercomplex& image, Hypercomplex& magnitude) {
        const std::array<double, 3> p{q.w, q.x, q.y};
        for (size_t k = 0; k < image.size(); ++k)
            for (size_t i = 0; i < 3; ++i) {
                image[k] += p[i] * t[i][k];
                magnitude[k] += std::abs(p[i]) * std::abs(t[i][k]);
            }
    };
    apply(settings.origin, plane.origin, plane.originMagnitude);
    for (size_t k = 0; k < o.size(); ++k) {
        plane.origin[k] += o[k];
        plane.originMagnitude[k] += std::abs(o[k]);
    }
    apply(settings.u, plane.u, plane.uMagnitude);
    apply(settings.v, plane.v, plane.vMagnitude);
    return plane;
}

// The julia kinds and the slice kind: cells as segments through the set's excludesSegment,
// centres as boxes through its includesBox.
class SetProver {
  public:
    SetProver(const JuliaSet& set, const PlaneInAlgebra& plane, const PlaneView& view)
        : set_(set), plane_(plane), view_(view) {
        const double reach = viewReach(view);
        const Complex turn = viewTurn(view);
        double terms = 0, down = 0;
        for (size_t k = 0; k < plane.origin.size(); ++k) {
            terms = std::max(terms, plane.originMagnitude[k] +
                                        reach * (plane.uMagnitude[k] + plane.vMagnitude[k]));
            down = std::max(down, std::abs(turn.imag()) * plane.uMagnitude[k] +
                                      std::abs(turn.real()) * plane.vMagnitude[k]);
        }
        // The plane point's error carried into the algebra, and the algebra point's own.
        margin_ = 2 * kRounding * terms;
        halfDown_ = 0.5 * view.pixelSize() * down * (1 + kRounding);
    }

    bool hits(int px, int py) const {
        return set_.includesBox(plane_.at(view_.pointAt(px + 0.5, py + 0.5)), margin_);
    }

    // The square's points are its middle line's, moved by at most half its height down or up
    // the image.
    bool misses(const Square& s) const {
        const double y = s.y0 + 0.5 * s.size;
        return set_.excludesSegment(plane_.at(view_.pointAt(s.x0, y)),
                                    plane_.at(view_.pointAt(s.x0 + s.size, y)),
                                    s.size * halfDown_ + margin_);
    }

  private:
    const JuliaSet& set_;
    PlaneInAlgebra plane_;
    PlaneView view_;
    double margin_ = 0, halfDown_ = 0;
};

// Complex interval arithmetic for the parameter plane: a box of complex numbers.
struct ComplexBox {
    Interval re, im;
};

ComplexBox operator+(const ComplexBox& a, const ComplexBox& b) {
    return {a.re + b.re, a.im + b.im};
}

ComplexBox times(const ComplexBox& a, const ComplexBox& b) {
    return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re};
}

ComplexBox power(const ComplexBox& z, int degree) {
    if (degree == 2) return {square(z.re) - square(z.im), 2.0 * (z.re * z.im)};
    ComplexBox p = z;
    for (int k = 1; k < degree; ++k)
        p = times(p, z);
    return p;
}

// Bounds of |z|^2 over the box (the upper one infinite where a bound is not finite).
double lowerAbsSquared(const ComplexBox& z) {
    return std::max(0.0, roundedDown(lowerSquare(z.re) + lowerSquare(z.im)));
}
double upperAbsSquared(const ComplexBox& z) {
    const double r = roundedUp(square(z.re).hi + square(z.im).hi);
    return std::isfinite(r) ? r : INFINITY;
}

// A disc of complex numbers: every centre + delta with |delta| <= radius (midpoint-radius
// arithmetic: the orbit's error is carried by its norm, which turns do not widen).
struct ComplexDisc {
    Complex centre{};
    double radius = 0;
};

double upperAbs(Complex z) {
    return roundedUp(std::hypot(z.real(), z.imag()));  // hypot: within an ulp
}

// Encloses {w^d + c : w in z}: the centre's image in interval arithmetic, re-centred on its
// box, whose half diagonal joins the radius, and |(m + delta)^d - m^d| <= (|m| + r)^d - |m|^d
// (the binomial expansion: complex numbers commute), which grows with |m|.
ComplexDisc nextDisc(const ComplexDisc& z, const ComplexDisc& c, int degree) {
    const ComplexBox image =
        power(ComplexBox{Interval::point(z.centre.real()), Interval::point(z.centre.imag())},
              degree) +
        ComplexBox{Interval::point(c.centre.real()), Interval::point(c.centre.imag())};
    const Interval m = Interval::point(upperAbs(z.centre));
    const Interval grown = m + Interval::point(z.radius);
    Interval grownPower = grown, mPower = m;
    for (int k = 1; k < degree; ++k) {
        grownPower = grownPower * grown;
        mPower = mPower * m;
    }
    const Complex mid(0.5 * (image.re.lo + image.re.hi), 0.5 * (image.im.lo + image.im.hi));
    const double hx = roundedUp(std::max(image.re.hi - mid.real(), mid.real() - image.re.lo));
    const double hy = roundedUp(std::max(image.im.hi - mid.imag(), mid.imag() - image.im.lo));
    const double corner = roundedUp(std::sqrt(roundedUp(hx * hx + hy * hy)));
    return {mid, roundedUp(roundedUp(corner + (grownPower - mPower).hi) + c.radius)};
}

// The mandelbrot kind: c in K_N where z_1 .. z_N of z_0 = 0, z_{n+1} = z_n^d + c stay within
// max(2, |c|) (estimateMandelbrot's membership).
class MandelbrotProver {
  public:
    MandelbrotProver(int degree, int iterations, const PlaneView& view)
        : degree_(degree),
          iterations_(iterations),
          view_(view),
          margin_(kRounding * viewReach(view)) {}

    // The centre's orbit in disc arithmetic (ComplexDisc): a box would wrap the orbit's turns
    // into ever wider boxes, and near an attracting cycle whose multiplier is not far below 1
    // they grow without bound.
    bool hits(int px, int py) const {
        const Complex c = view_.pointAt(px + 0.5, py + 0.5);
        // Every c within the rounding margin of the exact centre: max(2, |c|) >= ball.
        const ComplexDisc disc{c, margin_};
        const double ball =
            std::max(2.0, roundedDown(roundedDown(std::hypot(c.real(), c.imag())) - margin_));
        ComplexDisc z{};
        for (int n = 1; n <= iterations_; ++n) {
            z = nextDisc(z, disc, degree_);
            if (!(roundedUp(upperAbs(z.centre) + z.radius) <= ball)) return false;
        }
        return true;
    }

    // The box of c enclosing the square's corners, widened by the rounding margin.
    bool misses(const Square& s) const {
        std::array<Complex, 4> corners{
            view_.pointAt(s.x0, s.y0), view_.pointAt(s.x0 + s.size, s.y0),
            view_.pointAt(s.x0, s.y0 + s.size), view_.pointAt(s.x0 + s.size, s.y0 + s.size)};
        ComplexBox c{Interval::point(corners[0].real()), Interval::point(corners[0].imag())};
        for (const Complex& p : corners) {
            c.re = {std::min(c.re.lo, p.real()), std::max(c.re.hi, p.real())};
            c.im = {std::min(c.im.lo, p.imag()), std::max(c.im.hi, p.imag())};
        }
        c.re = {roundedDown(c.re.lo - margin_), roundedUp(c.re.hi + margin_)};
        c.im = {roundedDown(c.im.lo - margin_), roundedUp(c.im.hi + margin_)};
        // Every c of the box has max(2, |c|)^2 <= ball.
        const double ball = std::max(4.0, upperAbsSquared(c));
        const double widest = 2 * std::sqrt(ball);
        ComplexBox z{};
        for (int n = 1; n <= iterations_; ++n) {
            z = power(z, degree_) + c;
            if (lowerAbsSquared(z) > ball) return true;
            if (!(z.re.width() <= widest && z.im.width() <= widest)) return false;
        }
        return false;
    }

  private:
    int degree_, iterations_;
    PlaneView view_;
    double margin_;
};

template <class Prover>
bool missesSquare(const Prover& prover, const Square& s, int depth) {
    if (prover.misses(s)) return true;
    if (depth == 0) return false;
    const double half = 0.5 * s.size;
    for (int part = 0; part < 4; ++part)
        if (!missesSquare(prover, Square{s.x0 + half * (part % 2), s.y0 + half * (part / 2), half},
                          depth - 1))
            return false;
    return true;
}

template <class Prover>
PlaneCertificate classifyPixels(const Prover& prover, const PlaneView& view,
                                const WorkOptions& options) {
    PlaneCertificate result;
    result.width = view.pixelWidth;
    result.height = view.pixelHeight;
    result.classes.assign(size_t(view.pixelWidth) * size_t(view.pixelHeight),
                          uint8_t(PixelClass::kUndecided));
    const ParallelOptions parallel =
        imageParallelOptions(options, view.pixelWidth, view.pixelHeight);
    const auto start = std::chrono::steady_clock::now();
    result.completed =
        parallelForTiles(view.pixelWidth, view.pixelHeight, parallel, [&](const Tile& tile, int) {
            for (int py = tile.y0; py < tile.y1; ++py)
                for (int px = tile.x0; px < tile.x1; ++px) {
                    uint8_t& cell =
                        result.classes[size_t(py) * size_t(view.pixelWidth) + size_t(px)];
                    if (prover.hits(px, py))
                        cell = uint8_t(PixelClass::kHit);
                    else if (missesSquare(prover, Square{double(px), double(py), 1.0},
                                          kSubdivisions))
                        cell = uint8_t(PixelClass::kMissed);
                }
        });
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.threads = parallel.threads;
    for (uint8_t c : result.classes) {
        result.counts.missed += PixelClass(c) == PixelClass::kMissed;
        result.counts.hit += PixelClass(c) == PixelClass::kHit;
        result.counts.undecided += PixelClass(c) == PixelClass::kUndecided;
    }
    return result;
}

// The set a set kind draws, with its plane in the algebra (renderPlane's choices).
struct ProvedSet {
    std::shared_ptr<const JuliaSet> set;
    PlaneInAlgebra plane;
};

ProvedSet provedSetOf(const Scene& scene) {
    const PlaneSettings& settings = scene.plane;
    if (settings.kind != PlaneKind::Slice) {
        // The julia kinds: the plane span{1, u} of the quaternions' set that the drawn scene's
        // complex restriction lives in.
        const Scene drawn = planeDrawnScene(scene);
        const Quaternion axis = complexRestrictionOfScene(drawn).axis;
        return {std::make_shared<const QuaternionJuliaSet>(planeJuliaSet(drawn)),
                exactPlane({}, hypercomplexOf(Quaternion(1)), hypercomplexOf(axis))};
    }
    const PlaneInAlgebra plane = exactPlane(hypercomplexOf(settings.origin),
                                            hypercomplexOf(settings.u), hypercomplexOf(settings.v));
    if (algebraRules(scene.fractal.algebra).quaternionSet)
        return {std::make_shared<const QuaternionJuliaSet>(planeJuliaSet(scene)), plane};
    const Fractal fractal = planeHypercomplexFractal(scene);
    if (algebraDimension(scene.fractal.algebra) == 8)
        return {fractal.sharedSet(), planeThroughSlice(settings, fractal.slice())};
    return {fractal.sharedSet(), plane};
}

}  // namespace

void validatePlaneCertificate(const Scene& scene) {
    validatePlaneScene(scene);
    if (scene.plane.kind == PlaneKind::Basins)
        throw UserError("plane.kind",
                        "plane.kind = \"basins\" has no certificate: its colours are basins of "
                        "attraction, not the set K_N that --certify proves; use plane.kind = "
                        "\"julia\" or \"slice\"");
    if (scene.plane.kind == PlaneKind::Mandelbrot) return;
    if (auto part = provedSetOf(scene).set->unprovablePart())
        throw UserError("fractal.formula",
                        "fractal.formula = \"" + scene.fractal.formula +
                            "\" cannot be certified: " + *part +
                            " has no interval extension (interval/interval_element.h)");
}

PlaneCertificate certifyPlane(const Scene& scene, const WorkOptions& options) {
    validatePlaneCertificate(scene);
    const PlaneView view = planeViewFromScene(scene);
    if (scene.plane.kind == PlaneKind::Mandelbrot) {
        const Scene drawn = planeDrawnScene(scene);
        return classifyPixels(
            MandelbrotProver(planeMultibrotDegree(drawn), drawn.plane.maxIterations, view), view,
            options);
    }
    const ProvedSet proved = provedSetOf(scene);
    return classifyPixels(SetProver(*proved.set, proved.plane, view), view, options);
}

}  // namespace quaternia
