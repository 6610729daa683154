#include "quaternia/plane/plane_render.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <vector>

#include "quaternia/algebra/formula.h"
#include "quaternia/dynamics/basins.h"
#include "quaternia/dynamics/mandelbrot.h"
#include "quaternia/fractal/algebra_rules.h"
#include "quaternia/fractal/distance.h"
#include "quaternia/fractal/hypercomplex_julia.h"
#include "quaternia/image/png_writer.h"
#include "quaternia/render/render.h"
#include "quaternia/render/sample_pattern.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_fractal.h"
#include "quaternia/util/error.h"
#include "quaternia/util/parallel.h"

namespace quaternia {
namespace {

std::string kindName(const Scene& scene) {
    return std::get<std::string>(findParameter("plane.kind")->read(scene));
}

}  // namespace

QuaternionJuliaSet planeJuliaSet(const Scene& scene) {
    return QuaternionJuliaSet(compileFormula(scene.fractal.formula, scene.fractal.c),
                              scene.plane.maxIterations, scene.fractal.bailout);
}

// Checked by compiling the formula with a marker c: its constant must be that c and its top
// term z^d alone.
int planeMultibrotDegree(const Scene& scene) {
    const Quaternion marker{0.5, 0.25, 0.125, 0.0625};
    auto power = compileFormula(scene.fractal.formula, marker).powerForm();
    if (!power || power->scale != 1 || !(power->constant == marker))
        throw UserError("fractal.formula",
                        "plane.kind = \"mandelbrot\" draws the Mandelbrot set of z^d + c, but "
                        "fractal.formula = \"" +
                            scene.fractal.formula + "\" is not of that form");
    return power->degree;
}

namespace {

// An escaped point takes the palette's colour, darkened towards the interior within two pixels
// of the set, so that filaments thinner than a pixel stay visible (the distance estimate as a
// shading term, Quilez, "distance rendering for fractals").
Color escapeShade(bool inside, double smoothIteration, double distance, double pixelSize) {
    if (inside) return interiorColor();
    double t = std::clamp(distance / (2 * pixelSize), 0.0, 1.0);
    return lerp(interiorColor(), escapeColor(smoothIteration), std::sqrt(t));
}

// What a sample gives: its colour, and the label of the point (PlaneImage::labels).
struct PlaneSample {
    Color color;
    int32_t label = 0;
};

// The label of an escape estimate: the escape iteration, -1 for a point that stayed.
template <typename Estimate>
int32_t escapeLabel(const Estimate& e) {
    return e.inside ? -1 : int32_t(e.escapeIteration);
}

// Runs sample(point) at `samples` stratified positions of every pixel and stores the mean
// colour, and the first sample's label.
template <typename Sampler>
PlaneImage renderSamples(const PlaneView& view, int samples, const PlaneRenderOptions& options,
                         const Sampler& sample) {
    PlaneImage result;
    result.image = Image(view.pixelWidth, view.pixelHeight);
    result.labels.assign(size_t(view.pixelWidth) * size_t(view.pixelHeight), 0);
    const ParallelOptions parallel =
        imageParallelOptions(options, view.pixelWidth, view.pixelHeight);
    auto start = std::chrono::steady_clock::now();
    result.completed =
        parallelForTiles(view.pixelWidth, view.pixelHeight, parallel, [&](const Tile& tile, int) {
            for (int py = tile.y0; py < tile.y1; ++py) {
                for (int px = tile.x0; px < tile.x1; ++px) {
                    Color sum;
                    for (int k = 0; k < samples; ++k) {
                        auto [sx, sy] = samplePosition(k, samples, px, py);
                        const PlaneSample s = sample(view.pointAt(px + sx, py + sy));
                        sum += s.color;
                        if (k == 0)
                            result.labels[size_t(py) * size_t(view.pixelWidth) + size_t(px)] =
                                s.label;
                    }
                    Color mean = sum / double(samples);
                    result.image.at(px, py) =
                        Rgba{float(mean.x), float(mean.y), float(mean.z), 1.0f};
                }
            }
        });
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.threads = parallel.threads;
    result.samples = int64_t{view.pixelWidth} * view.pixelHeight * samples;
    return result;
}

// Julia-set kinds: each plane point z goes through `estimateAt(z)` (a DistanceEstimate of the
// set at the point the plane point stands for). `scale` is the length in the algebra of one
// plane unit.
template <typename EstimateAt>
PlaneImage renderEscape(const Scene& scene, const PlaneView& view, double scale,
                        const PlaneRenderOptions& options, const EstimateAt& estimateAt) {
    const double pixelSize = view.pixelSize() * scale;
    if (scene.plane.kind == PlaneKind::JuliaBoundary) {
        const double lineWidth = scene.plane.boundaryWidth * pixelSize;
        return renderSamples(view, scene.render.samples, options, [&](std::complex<double> z) {
            DistanceEstimate e = estimateAt(z);
            return PlaneSample{
                !e.inside && e.distance < lineWidth ? boundaryColor() : interiorColor(),
                escapeLabel(e)};
        });
    }
    return renderSamples(view, scene.render.samples, options, [&](std::complex<double> z) {
        DistanceEstimate e = estimateAt(z);
        return PlaneSample{escapeShade(e.inside, e.smoothIteration, e.distance, pixelSize),
                           escapeLabel(e)};
    });
}

// The quaternion kinds: each plane point is a quaternion (`toQuaternion`), iterated by
// QuaternionJuliaSet, the one iteration of the library, so that a complex image and the same plane
// sliced out of H go through the very same arithmetic.
template <typename ToQuaternion>
PlaneImage renderJulia(const Scene& scene, const PlaneView& view, double scale,
                       const PlaneRenderOptions& options, const ToQuaternion& toQuaternion) {
    const QuaternionJuliaSet set = planeJuliaSet(scene);
    return renderEscape(scene, view, scale, options,
                        [&](std::complex<double> z) { return set.estimate(toQuaternion(z)); });
}

}  // namespace

Fractal planeHypercomplexFractal(const Scene& scene) {
    Scene planeScene = scene;
    planeScene.fractal.maxIterations = scene.plane.maxIterations;
    return hypercomplexFractalFromScene(planeScene);
}

namespace {

// The slice kind in another algebra: plane.origin + x plane.u + y plane.v is the algebra's
// point (components 1, i, j, k) for the 4-component algebras, as for the quaternions; for the
// 8-component ones its first three components are a point of the 3D slice (slice.origin,
// slice.axes), which maps it into the algebra. Membership is HypercomplexJuliaSet::contains,
// K_N exactly as the renderer and the mesher take it; the estimate only colours escaping points.
PlaneImage renderHypercomplexSlice(const Scene& scene, const PlaneView& view,
                                   const PlaneRenderOptions& options) {
    const auto fractal = planeHypercomplexFractal(scene);
    const HypercomplexJuliaSet& set = *fractal.setAs<HypercomplexJuliaSet>();
    const PlaneSettings& plane = scene.plane;
    const bool throughSlice = algebraDimension(scene.fractal.algebra) == 8;
    const double scale = std::sqrt(norm(plane.u) * norm(plane.v));
    return renderEscape(scene, view, scale, options, [&](std::complex<double> z) {
        const Quaternion q = plane.origin + plane.u * z.real() + plane.v * z.imag();
        const Hypercomplex point = throughSlice ? fractal.slice().fromWorld(Point3d(q.w, q.x, q.y))
                                                : Hypercomplex{q.w, q.x, q.y, q.z, 0, 0, 0, 0};
        if (set.contains(point)) {
            DistanceEstimate inside;
            inside.inside = true;
            return inside;
        }
        DistanceEstimate e = set.estimate(point);
        e.inside = false;
        return e;
    });
}

// Whether the scene's algebra takes the quaternions' own set, the expanded polynomial, whose
// complex restriction the planes of complex dynamics draw (algebraRules); the others reach them
// through the copy of C their formula keeps (planeDrawnScene) or draw a slice.
bool ownQuaternionSet(const Scene& scene) {
    return algebraRules(scene.fractal.algebra).quaternionSet;
}

}  // namespace

Scene planeDrawnScene(const Scene& scene) {
    if (ownQuaternionSet(scene)) return scene;
    const bool mandelbrot = scene.plane.kind == PlaneKind::Mandelbrot;
    Scene probe = scene;
    if (mandelbrot) {
        probe.fractal.c = Quaternion(0.5, 0.25, 0, 0);
        probe.fractal.cUpper = {};
    }
    const auto axis =
        planeHypercomplexFractal(probe).setAs<HypercomplexJuliaSet>()->formula().complexAxis();
    if (!axis || (mandelbrot && !inPlane(kUnitI, *axis)))
        throw UserError("plane.kind",
                        "plane.kind = \"" + kindName(scene) +
                            "\" needs a plane span{1, u} (u^2 = -1) holding every constant of "
                            "fractal.formula and fractal.c, and fractal.algebra = \"" +
                            std::string(algebraName(scene.fractal.algebra)) +
                            "\" has none for them; plane.kind = \"slice\" draws any formula");
    Scene quaternion = scene;
    quaternion.fractal.algebra = Algebra::kQuaternion;
    quaternion.fractal.cUpper = {};
    quaternion.fractal.cComponents = 4;
    quaternion.slice.origin.clear();
    quaternion.slice.axes.clear();
    return quaternion;
}

Color escapeColor(double smoothIteration) {
    // a + b cos(2 pi (f t + d)) per channel, t growing like the logarithm of the count so that
    // the bands keep a steady width from the outside in to deep zooms.
    const double t = std::log1p(std::max(0.0, smoothIteration));
    const Color phase(0.60, 0.70, 0.80);
    auto channel = [&](double d) { return 0.5 + 0.5 * std::cos(2 * std::numbers::pi * (t + d)); };
    return Color(channel(phase.x), channel(phase.y), channel(phase.z));
}

Color interiorColor() {
    return Color(0.02, 0.02, 0.05);
}

Color boundaryColor() {
    return Color(1.0, 0.86, 0.55);
}

PlaneView planeViewFromScene(const Scene& scene) {
    PlaneView view;
    view.centre = {scene.plane.center[0], scene.plane.center[1]};
    view.width = scene.plane.width;
    view.rotationDegrees = scene.plane.rotationDegrees;
    view.pixelWidth = scene.render.width;
    view.pixelHeight = scene.render.height;
    return view;
}

ComplexRestriction complexRestrictionOfScene(const Scene& scene) {
    if (!ownQuaternionSet(scene)) return complexRestrictionOfScene(planeDrawnScene(scene));
    auto restriction =
        restrictToComplexPlane(compileFormula(scene.fractal.formula, scene.fractal.c));
    if (!restriction)
        throw UserError("fractal.formula",
                        "plane.kind = \"" + kindName(scene) +
                            "\" needs a complex polynomial, but the coefficients of "
                            "fractal.formula = \"" +
                            scene.fractal.formula +
                            "\" share no plane span{1, u} of H; plane.kind = \"slice\" draws "
                            "any formula");
    if (restriction->axis == -kUnitI) {
        // x + y(-i) read as x - y i: conjugating every coefficient turns the plane back.
        std::vector<Complex> coefficients = restriction->polynomial.coefficients();
        for (Complex& a : coefficients)
            a = std::conj(a);
        restriction = ComplexRestriction{ComplexPolynomial(std::move(coefficients)), kUnitI};
    }
    return *restriction;
}

void validatePlaneScene(const Scene& scene) {
    validateScene(scene);
    const PlaneSettings& plane = scene.plane;
    if (!ownQuaternionSet(scene)) {
        planeHypercomplexFractal(scene);  // formula, bailout and slice keys
        if (plane.kind != PlaneKind::Slice) {
            validatePlaneScene(planeDrawnScene(scene));
            return;
        }
    } else {
        planeJuliaSet(scene);  // the formula compiles, the bailout is usable
    }
    switch (plane.kind) {
        case PlaneKind::Julia:
        case PlaneKind::JuliaBoundary:
        case PlaneKind::Basins:
            complexRestrictionOfScene(scene);
            break;
        case PlaneKind::Mandelbrot:
            planeMultibrotDegree(scene);
            break;
        case PlaneKind::Slice: {
            if (normSquared(plane.u) == 0) throw UserError("plane.u", "plane.u must not be zero");
            if (normSquared(plane.v) == 0) throw UserError("plane.v", "plane.v must not be zero");
            // |u|^2 |v|^2 - (u . v)^2 is the squared area the two span; below 1e-18 of its
            // largest value (the sine of their angle below 1e-9), they span no plane.
            double uu = normSquared(plane.u), vv = normSquared(plane.v);
            double uv = dot(plane.u, plane.v);
            if (uu * vv - uv * uv <= 1e-18 * uu * vv)
                throw UserError("plane.v",
                                "plane.v is parallel to plane.u; a slice needs two "
                                "independent directions of H");
            if (algebraDimension(scene.fractal.algebra) == 8) {
                // The plane lies in the 3D slice: its points have three coordinates.
                for (const auto& [key, q] :
                     {std::pair<const char*, const Quaternion&>{"plane.origin", plane.origin},
                      {"plane.u", plane.u},
                      {"plane.v", plane.v}})
                    if (q.z != 0)
                        throw UserError(key, std::string(key) + ": with fractal.algebra = \"" +
                                                 std::string(algebraName(scene.fractal.algebra)) +
                                                 "\" the plane lies in the 3D slice "
                                                 "(slice.origin, slice.axes), so its fourth "
                                                 "component must be 0");
            }
            break;
        }
    }
}

PlaneImage renderPlane(const Scene& scene, const PlaneRenderOptions& options) {
    validatePlaneScene(scene);
    if (!ownQuaternionSet(scene) && scene.plane.kind != PlaneKind::Slice)
        return renderPlane(planeDrawnScene(scene), options);
    const PlaneView view = planeViewFromScene(scene);
    const PlaneSettings& plane = scene.plane;
    switch (plane.kind) {
        case PlaneKind::Julia:
        case PlaneKind::JuliaBoundary: {
            const ComplexRestriction restriction = complexRestrictionOfScene(scene);
            return renderJulia(scene, view, 1.0, options,
                               [&](std::complex<double> z) { return restriction.toQuaternion(z); });
        }
        case PlaneKind::Slice: {
            if (!ownQuaternionSet(scene)) return renderHypercomplexSlice(scene, view, options);
            const double scale = std::sqrt(norm(plane.u) * norm(plane.v));
            return renderJulia(scene, view, scale, options, [&](std::complex<double> z) {
                return plane.origin + plane.u * z.real() + plane.v * z.imag();
            });
        }
        case PlaneKind::Mandelbrot: {
            const int degree = planeMultibrotDegree(scene);
            const int iterations = plane.maxIterations;
            const double pixelSize = view.pixelSize();
            return renderSamples(view, scene.render.samples, options, [&](std::complex<double> c) {
                MandelbrotEstimate e = estimateMandelbrot(c, iterations, degree);
                return PlaneSample{escapeShade(e.inside, e.smoothIteration, e.distance, pixelSize),
                                   escapeLabel(e)};
            });
        }
        case PlaneKind::Basins: {
            BasinOptions basinOptions;
            basinOptions.maxIterations = plane.maxIterations;
            basinOptions.samples = scene.render.samples;
            basinOptions.threads = options.threads;
            basinOptions.cancel = options.cancel;
            auto start = std::chrono::steady_clock::now();
            BasinImage basins =
                renderBasins(complexRestrictionOfScene(scene).polynomial, view, basinOptions);
            PlaneImage result;
            result.image = std::move(basins.image);
            result.labels = std::move(basins.labels);
            result.completed = basins.completed;
            result.threads = resolveThreadCount(options.threads);
            result.samples = int64_t{view.pixelWidth} * view.pixelHeight * scene.render.samples;
            result.seconds =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            return result;
        }
    }
    return {};
}

uint64_t planeMemoryBytes(const Scene& scene) {
    const uint64_t pixels = uint64_t(scene.render.width) * uint64_t(scene.render.height);
    const PngFormat format{scene.render.width, scene.render.height, scene.render.bitDepth,
                           PngColorType::Rgba};
    return 2 * pixels * sizeof(Rgba) + pixels * sizeof(int32_t) + 2 * pngBytesBound(format);
}

}  // namespace quaternia
