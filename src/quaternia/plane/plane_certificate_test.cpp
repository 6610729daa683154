#include "quaternia/plane/plane_certificate.h"

#include <gtest/gtest.h>

#include <complex>
#include <functional>
#include <string>

#include "quaternia/algebra/test_helpers.h"
#include "quaternia/dynamics/mandelbrot.h"
#include "quaternia/fractal/algebra_rules.h"
#include "quaternia/plane/plane_render.h"
#include "quaternia/plane/plane_test_scenes.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_file.h"

namespace quaternia {
namespace {

using testing::thrownError;
using Complex = std::complex<double>;

using testing::kBasilica;
using testing::kRabbit;
using testing::onThreads;

Scene planeScene(const std::string& kind, std::vector<double> c, int width, int height) {
    Scene scene = testing::planeTestScene(kind, c, width, height);
    setParameter(scene, "plane.max_iterations", int64_t{100});
    return scene;
}

// Membership of the plane point z in the kind's K_N by plain floating-point iteration, the
// plane mapped into the algebra as the renderer maps it (written out again here).
std::function<bool(Complex)> floatMembership(const Scene& scene) {
    const PlaneSettings& plane = scene.plane;
    if (plane.kind == PlaneKind::Mandelbrot) {
        const int degree = planeMultibrotDegree(scene);
        return [=](Complex c) { return inMandelbrotSet(c, plane.maxIterations, degree); };
    }
    if (plane.kind != PlaneKind::Slice) {
        const Scene drawn = planeDrawnScene(scene);
        const ComplexRestriction restriction = complexRestrictionOfScene(drawn);
        auto set = std::make_shared<QuaternionJuliaSet>(planeJuliaSet(drawn));
        return [=](Complex z) { return set->contains(restriction.toQuaternion(z)); };
    }
    auto toH = [plane](Complex z) {
        return plane.origin + plane.u * z.real() + plane.v * z.imag();
    };
    if (algebraRules(scene.fractal.algebra).quaternionSet) {
        auto set = std::make_shared<QuaternionJuliaSet>(planeJuliaSet(scene));
        return [=](Complex z) { return set->contains(toH(z)); };
    }
    auto fractal = std::make_shared<Fractal>(planeHypercomplexFractal(scene));
    const bool throughSlice = algebraDimension(scene.fractal.algebra) == 8;
    return [=](Complex z) {
        const Quaternion q = toH(z);
        return fractal->set().contains(throughSlice
                                           ? fractal->slice().fromWorld(Point3d(q.w, q.x, q.y))
                                           : Hypercomplex{q.w, q.x, q.y, q.z, 0, 0, 0, 0});
    };
}

// Every certain class against the iteration: a missed cell's centre and corners escape (and
// the image's own sample at the centre escaped), a hit cell's centre stays (in the image too).
// Both certain classes must occur, so that the check is not empty.
PlaneCertificate expectClassesAgreeWithIteration(const Scene& scene) {
    const PlaneCertificate certificate = certifyPlane(scene, onThreads(2));
    const PlaneView view = planeViewFromScene(scene);
    const auto inside = floatMembership(scene);
    const PlaneImage image = renderPlane(scene);  // one sample: the pixel's centre
    EXPECT_EQ(certificate.width, view.pixelWidth);
    EXPECT_EQ(certificate.height, view.pixelHeight);
    EXPECT_EQ(certificate.counts.missed + certificate.counts.hit + certificate.counts.undecided,
              int64_t{view.pixelWidth} * view.pixelHeight);
    EXPECT_GT(certificate.counts.missed, 0);
    EXPECT_GT(certificate.counts.hit, 0);
    int wrong = 0;
    for (int py = 0; py < view.pixelHeight; ++py)
        for (int px = 0; px < view.pixelWidth; ++px) {
            const size_t n = size_t(py) * size_t(view.pixelWidth) + size_t(px);
            const PixelClass c = certificate.at(px, py);
            const bool stayed = image.labels[n] == -1;
            bool right = true;
            if (c == PixelClass::kHit) right = stayed && inside(view.pointAt(px + 0.5, py + 0.5));
            if (c == PixelClass::kMissed) {
                right = !stayed && !inside(view.pointAt(px + 0.5, py + 0.5));
                for (int corner = 0; corner < 4; ++corner)
                    right = right && !inside(view.pointAt(px + corner % 2, py + corner / 2));
            }
            if (!right && wrong++ < 5)
                ADD_FAILURE() << "pixel (" << px << ", " << py << ") class " << int(c);
        }
    EXPECT_EQ(wrong, 0);
    return certificate;
}

TEST(PlaneCertificate, BasilicaAndRabbitClassesAgreeWithIteration) {
    for (const auto& c : {kBasilica, kRabbit}) {
        Scene scene = planeScene("julia", c, 96, 72);
        setParameter(scene, "plane.width", 3.2);
        expectClassesAgreeWithIteration(scene);
        setParameter(scene, "plane.kind", std::string("julia-boundary"));
        expectClassesAgreeWithIteration(scene);
    }
}

TEST(PlaneCertificate, RotatedViewClassesAgreeWithIteration) {
    Scene scene = planeScene("julia", kRabbit, 80, 60);
    setParameter(scene, "plane.center", std::vector<double>{0.1, -0.2});
    setParameter(scene, "plane.width", 2.5);
    setParameter(scene, "plane.rotation", 33.0);
    expectClassesAgreeWithIteration(scene);
}

TEST(PlaneCertificate, MandelbrotClassesAgreeWithIteration) {
    Scene scene = planeScene("mandelbrot", kBasilica, 96, 72);
    setParameter(scene, "plane.center", std::vector<double>{-0.6, 0});
    setParameter(scene, "plane.width", 3.0);
    setParameter(scene, "plane.rotation", 10.0);
    expectClassesAgreeWithIteration(scene);
    setParameter(scene, "fractal.formula", std::string("z^3 + c"));
    setParameter(scene, "plane.center", std::vector<double>{0, 0});
    expectClassesAgreeWithIteration(scene);
}

TEST(PlaneCertificate, QuaternionSliceClassesAgreeWithIteration) {
    // A tilted plane off span{1, i}, through a c with a j part: no complex restriction.
    Scene scene = planeScene("slice", {-0.2, 0.3, 0.3, 0}, 80, 60);
    setParameter(scene, "plane.origin", std::vector<double>{0, 0, 0, 0.1});
    setParameter(scene, "plane.v", std::vector<double>{0, 0.6, 0.8, 0});
    setParameter(scene, "plane.width", 3.2);
    expectClassesAgreeWithIteration(scene);
}

TEST(PlaneCertificate, CoquaternionAndOctonionSliceClassesAgreeWithIteration) {
    Scene coquaternion = planeScene("slice", {-0.3, 0.5, 0.2, -0.2}, 80, 60);
    setParameter(coquaternion, "fractal.algebra", std::string("coquaternion"));
    setParameter(coquaternion, "plane.v", std::vector<double>{0, 0.8, 0, 0.6});
    setParameter(coquaternion, "plane.width", 3.2);
    expectClassesAgreeWithIteration(coquaternion);
    // The 8-component plane goes through the 3D slice (slice.axes e0, e1, e6).
    Scene octonion = planeScene("slice", {-0.1226, 0.5, 0.2, 0.2, 0.35, 0.1, 0.29, 0.1}, 80, 60);
    setParameter(octonion, "fractal.algebra", std::string("octonion"));
    setParameter(octonion, "slice.axes", std::vector<double>{1, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0,
                                                             0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0});
    setParameter(octonion, "plane.v", std::vector<double>{0, 0.6, 0.8, 0});
    setParameter(octonion, "plane.width", 3.2);
    expectClassesAgreeWithIteration(octonion);
}

TEST(PlaneCertificate, BasilicaIsAlmostAllDecided) {
    Scene scene = planeScene("julia", kBasilica, 256, 256);
    setParameter(scene, "plane.max_iterations", int64_t{256});
    setParameter(scene, "plane.width", 3.2);
    const PlaneCertificate certificate = certifyPlane(scene, onThreads(2));
    EXPECT_TRUE(certificate.completed);
    // Measured: 3.9% (2556 pixels), all of them outside K_N by their centre: the cells that
    // J_c passes through or comes within a sixteenth of a pixel of.
    EXPECT_LT(certificate.counts.undecidedFraction(), 0.05);
}

TEST(PlaneCertificate, ClassesDoNotDependOnTheThreads) {
    Scene scene = planeScene("julia", kRabbit, 48, 40);
    EXPECT_EQ(certifyPlane(scene, onThreads(1)).classes, certifyPlane(scene, onThreads(2)).classes);
}

TEST(PlaneCertificate, RefusesBasinsAndFormulasWithoutIntervalExtension) {
    Scene basins = planeScene("basins", kRabbit, 16, 12);
    EXPECT_EQ(thrownError([&] { certifyPlane(basins); }).key(), "plane.kind");
    Scene bicomplex = planeScene("slice", kRabbit, 16, 12);
    setParameter(bicomplex, "fractal.algebra", std::string("bicomplex"));
    setParameter(bicomplex, "fractal.formula", std::string("log(z) + c"));
    const UserError error = thrownError([&] { validatePlaneCertificate(bicomplex); });
    EXPECT_EQ(error.key(), "fractal.formula");
    EXPECT_NE(std::string(error.what()).find("log"), std::string::npos) << error.what();
}

}  // namespace
}  // namespace quaternia
