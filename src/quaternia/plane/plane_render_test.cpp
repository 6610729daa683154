#include "quaternia/plane/plane_render.h"

#include <gtest/gtest.h>

#include <set>

#include "quaternia/algebra/test_helpers.h"
#include "quaternia/image/png_io.h"
#include "quaternia/scene/parameters.h"

namespace quaternia {
namespace {

using testing::thrownError;

Scene planeScene(const std::string& kind, std::vector<double> c, int width, int height,
                 int samples) {
    Scene scene = defaultScene();
    setParameter(scene, "plane.kind", kind);
    setParameter(scene, "fractal.c", c);
    setParameter(scene, "render.width", int64_t{width});
    setParameter(scene, "render.height", int64_t{height});
    setParameter(scene, "render.samples", int64_t{samples});
    setParameter(scene, "plane.max_iterations", int64_t{100});
    return scene;
}

bool isInterior(const Rgba& p) {
    Color interior = interiorColor();
    return p == Rgba{float(interior.x), float(interior.y), float(interior.z), 1.0f};
}

const std::vector<double> kRabbit = {-0.12256116687665, 0.74486176661974, 0, 0};

TEST(PlaneRender, EveryKindIsInTheParameterTable) {
    Scene scene = defaultScene();
    for (const char* kind : {"julia", "julia-boundary", "mandelbrot", "basins", "slice"})
        EXPECT_NO_THROW(setParameter(scene, "plane.kind", std::string(kind))) << kind;
    EXPECT_EQ(scene.plane.kind, PlaneKind::Slice);
    EXPECT_EQ(thrownError([&] { setParameter(scene, "plane.kind", std::string("julias")); }).key(),
              "plane.kind");
    EXPECT_EQ(thrownError([&] { setParameter(scene, "plane.width", 0.0); }).key(), "plane.width");
}

TEST(PlaneRender, SliceThroughComplexPlaneEqualsComplexJuliaImage) {
    // With c in span{1, i}, the (1, i) plane of H is invariant and K meets it in the complex
    // filled Julia set (docs/facts.md, Complex restriction): the same picture, pixel for pixel.
    for (std::vector<double> c : {std::vector<double>{-0.4, 0.6, 0, 0}, {-0.4, -0.6, 0, 0}}) {
        Scene julia = planeScene("julia", c, 64, 48, 2);
        setParameter(julia, "plane.center", std::vector<double>{0.1, -0.05});
        setParameter(julia, "plane.rotation", 20.0);
        Scene slice = julia;
        setParameter(slice, "plane.kind", std::string("slice"));
        setParameter(slice, "plane.u", std::vector<double>{1, 0, 0, 0});
        setParameter(slice, "plane.v", std::vector<double>{0, 1, 0, 0});
        auto juliaPng = encodePng(renderPlane(julia).image, 8);
        EXPECT_EQ(juliaPng, encodePng(renderPlane(slice).image, 8)) << "c = " << c[1] << " i";
        // A mirrored c draws a mirrored set, so the two c above must differ.
        setParameter(julia, "fractal.c", std::vector<double>{c[0], -c[1], 0, 0});
        EXPECT_NE(juliaPng, encodePng(renderPlane(julia).image, 8));
    }
}

TEST(PlaneRender, RealParameterSetIsRevolvedAboutTheRealAxis) {
    // Real c: (a, v) is in K iff a + |v| i is, so the (1, j) slice equals the (1, i) slice.
    Scene scene = planeScene("slice", {-1, 0, 0, 0}, 48, 32, 1);
    setParameter(scene, "plane.v", std::vector<double>{0, 0, 1, 0});
    Image j = renderPlane(scene).image;
    setParameter(scene, "plane.v", std::vector<double>{0, 1, 0, 0});
    EXPECT_EQ(j.pixels(), renderPlane(scene).image.pixels());
}

TEST(PlaneRender, FilledJuliaImageIsPointSymmetric) {
    // K = -K for z^2 + c; a view centred at 0 with an even size maps pixel centres to their
    // negatives exactly, and (-z)^2 = z^2 exactly in floating point.
    Image image = renderPlane(planeScene("julia", kRabbit, 64, 48, 1)).image;
    int inside = 0;
    for (int y = 0; y < 48; ++y) {
        for (int x = 0; x < 64; ++x) {
            EXPECT_EQ(image.at(x, y), image.at(63 - x, 47 - y)) << x << ", " << y;
            inside += isInterior(image.at(x, y));
        }
    }
    EXPECT_GT(inside, 100);
}

TEST(PlaneRender, HalfTurnOfTheViewIsPointReflection) {
    Scene scene = planeScene("julia", kRabbit, 64, 48, 1);
    setParameter(scene, "plane.center", std::vector<double>{0.3, 0.2});
    Image straight = renderPlane(scene).image;
    setParameter(scene, "plane.rotation", 180.0);
    Image turned = renderPlane(scene).image;
    // cos(pi) and sin(pi) are not exact in floating point, so a pixel on the edge of K may
    // change; every other one is equal to 1e-4.
    int differing = 0;
    for (int y = 0; y < 48; ++y) {
        for (int x = 0; x < 64; ++x) {
            const Rgba &a = straight.at(x, y), &b = turned.at(63 - x, 47 - y);
            differing += std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b) > 1e-4f;
        }
    }
    EXPECT_LE(differing, 64 * 48 / 200);
}

TEST(PlaneRender, BoundaryIsThinAndLiesOnTheEdgeOfK) {
    const int w = 128, h = 96;
    Scene scene = planeScene("julia", {-1, 0, 0, 0}, w, h, 1);  // the basilica
    scene.plane.width = 3.6;
    Image filled = renderPlane(scene).image;
    scene.plane.kind = PlaneKind::JuliaBoundary;
    Image boundary = renderPlane(scene).image;
    auto inK = [&](int x, int y) { return isInterior(filled.at(x, y)); };
    // Pixels of K next to one outside it, and the reverse: the edge of K in the image.
    auto onEdge = [&](int x, int y) {
        for (auto [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
            int nx = x + dx, ny = y + dy;
            if (nx >= 0 && ny >= 0 && nx < w && ny < h && inK(nx, ny) != inK(x, y)) return true;
        }
        return false;
    };
    auto nearEdge = [&](int x, int y, int radius) {
        for (int ny = std::max(0, y - radius); ny <= std::min(h - 1, y + radius); ++ny)
            for (int nx = std::max(0, x - radius); nx <= std::min(w - 1, x + radius); ++nx)
                if (onEdge(nx, ny)) return true;
        return false;
    };
    Color line = boundaryColor();
    int lit = 0, inside = 0, far = 0;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            inside += inK(x, y);
            if (boundary.at(x, y).r != float(line.x)) continue;
            ++lit;
            far += !nearEdge(x, y, 2);
        }
    }
    EXPECT_GT(lit, 200);
    EXPECT_LT(lit, inside / 2);
    EXPECT_EQ(far, 0);
}

TEST(PlaneRender, AntiAliasingGivesIntermediateValues) {
    Scene scene = planeScene("julia-boundary", kRabbit, 48, 36, 1);
    auto levels = [&] {
        std::set<float> values;
        const Image image = renderPlane(scene).image;
        for (const Rgba& p : image.pixels())
            values.insert(p.r);
        return values;
    };
    EXPECT_EQ(levels().size(), 2u);  // line or ground
    scene.render.samples = 9;
    std::set<float> blended = levels();
    EXPECT_GT(blended.size(), 5u);
    EXPECT_EQ(*blended.begin(), float(interiorColor().x));
}

TEST(PlaneRender, SmoothColouringIsContinuousOutsideTheSet) {
    // c = 0: K is the unit disc. Outside |z| > 1.3 neighbouring pixels differ little, although
    // the integer escape count changes across many of them.
    const int w = 160, h = 120;
    Scene scene = planeScene("julia", {0, 0, 0, 0}, w, h, 1);
    scene.plane.width = 6;
    Image image = renderPlane(scene).image;
    PlaneView view = planeViewFromScene(scene);
    float maxStep = 0;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x + 1 < w; ++x) {
            if (std::abs(view.pointAt(x + 0.5, y + 0.5)) < 1.3) continue;
            const Rgba &a = image.at(x, y), &b = image.at(x + 1, y);
            maxStep =
                std::max({maxStep, std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
        }
    }
    EXPECT_LT(maxStep, 0.15f);  // an integer count would jump by up to 0.9
}

TEST(PlaneRender, MandelbrotStandardViewHoldsTheCardioidCentreButNotOne) {
    Scene scene = planeScene("mandelbrot", {0, 0, 0, 0}, 90, 60, 1);
    setParameter(scene, "plane.center", std::vector<double>{-0.5, 0});
    scene.plane.width = 3;
    Image image = renderPlane(scene).image;
    PlaneView view = planeViewFromScene(scene);
    auto pixelOf = [&](double re, double im) {
        double s = view.pixelSize();
        return image.at(int((re + 0.5) / s + 45), int(30 - im / s));
    };
    EXPECT_TRUE(isInterior(pixelOf(0, 0)));       // centre of the main cardioid
    EXPECT_TRUE(isInterior(pixelOf(-1, 0)));      // centre of the period-2 disc
    EXPECT_FALSE(isInterior(pixelOf(1, 0)));      // 0, 1, 2, 5: escapes
    EXPECT_FALSE(isInterior(pixelOf(0.9, 0.9)));  // outside |c| <= 2 but in view: no
}

TEST(PlaneRender, ValidationNamesTheKeyToChange) {
    Scene scene = planeScene("slice", {-1, 0, 0, 0}, 16, 16, 1);
    scene.plane.u = Quaternion();
    EXPECT_EQ(thrownError([&] { validatePlaneScene(scene); }).key(), "plane.u");
    scene.plane.u = Quaternion(1, 1, 0, 0);
    scene.plane.v = Quaternion(-2, -2, 0, 0);
    EXPECT_EQ(thrownError([&] { validatePlaneScene(scene); }).key(), "plane.v");
    scene.plane.v = Quaternion(0, 0, 1, 0);
    scene.fractal.formula = "i*z*j*z + c";
    EXPECT_NO_THROW(validatePlaneScene(scene));  // a slice draws any formula
    for (PlaneKind kind :
         {PlaneKind::Julia, PlaneKind::JuliaBoundary, PlaneKind::Basins, PlaneKind::Mandelbrot}) {
        scene.plane.kind = kind;
        EXPECT_EQ(thrownError([&] { validatePlaneScene(scene); }).key(), "fractal.formula");
    }
    scene.fractal.formula = "z^2 + z + c";
    EXPECT_EQ(thrownError([&] { validatePlaneScene(scene); }).key(), "fractal.formula");
    scene.fractal.formula = "z^3 + c";
    EXPECT_NO_THROW(validatePlaneScene(scene));
}

// ---- Other algebras (issue 16) ------------------------------------------------------------

// The pixels drawn as the set (interior colour) of an image.
std::vector<bool> interiorMask(const Image& image) {
    std::vector<bool> mask;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            mask.push_back(isInterior(image.at(x, y)));
    return mask;
}

TEST(PlaneRender, OctonionSliceInTheQuaternionHalfIsTheQuaternionSlice) {
    // (a, 0)(c, 0) = (ac, 0): with c in the quaternion half and the default 3D slice (e0, e1,
    // e2), the plane through 1 and j is the quaternion one: the same set pixel for pixel.
    Scene quaternion = planeScene("slice", {-0.12, 0.7, 0.1, 0.05}, 64, 48, 1);
    setParameter(quaternion, "plane.v", std::vector<double>{0, 0, 1, 0});
    setParameter(quaternion, "plane.origin", std::vector<double>{0, 0.1, 0, 0});
    setParameter(quaternion, "fractal.bailout", 4.0);
    Scene octonion = quaternion;
    setParameter(octonion, "fractal.algebra", std::string("octonion"));
    setParameter(octonion, "fractal.c", std::vector<double>{-0.12, 0.7, 0.1, 0.05, 0, 0, 0, 0});
    const std::vector<bool> mask = interiorMask(renderPlane(quaternion).image);
    EXPECT_EQ(mask, interiorMask(renderPlane(octonion).image));
    EXPECT_GT(std::count(mask.begin(), mask.end(), true), 64 * 48 / 20);
    EXPECT_LT(std::count(mask.begin(), mask.end(), true), 64 * 48 / 2);
}

TEST(PlaneRender, BicomplexAndCoquaternionSlicesOfTheComplexPlaneAreTheComplexJuliaSet) {
    // i^2 = -1 in both algebras: span{1, i} is a subalgebra equal to C, and with c there the
    // (1, i) plane is the complex filled Julia set, membership for membership.
    Scene julia = planeScene("julia", kRabbit, 64, 48, 1);
    setParameter(julia, "fractal.bailout", 4.0);
    const std::vector<bool> mask = interiorMask(renderPlane(julia).image);
    EXPECT_GT(std::count(mask.begin(), mask.end(), true), 64 * 48 / 20);
    for (const char* algebra : {"bicomplex", "coquaternion"}) {
        Scene slice = julia;
        setParameter(slice, "plane.kind", std::string("slice"));
        setParameter(slice, "fractal.algebra", std::string(algebra));
        const std::vector<bool> other = interiorMask(renderPlane(slice).image);
        size_t differ = 0;
        for (size_t n = 0; n < mask.size(); ++n)
            differ += mask[n] != other[n];
        EXPECT_EQ(differ, 0u) << algebra;
    }
}

TEST(PlaneRender, EightComponentSlicePlaneFollowsSliceAxes) {
    // The plane lies in the 3D slice: with slice.axes e0, e1, e6 its third direction is e6.
    // For octonion z^2 + c with c in span{1, i}, e6 behaves as j does in H (a turn of Im O
    // fixing i, an automorphism of the orbit), so the (1, e6) plane is the quaternion (1, j) one.
    Scene quaternion = planeScene("slice", kRabbit, 48, 32, 1);
    setParameter(quaternion, "plane.v", std::vector<double>{0, 0, 1, 0});
    setParameter(quaternion, "fractal.bailout", 4.0);
    Scene octonion = quaternion;
    setParameter(octonion, "fractal.algebra", std::string("octonion"));
    setParameter(octonion, "fractal.c",
                 std::vector<double>{kRabbit[0], kRabbit[1], 0, 0, 0, 0, 0, 0});
    setParameter(octonion, "slice.axes", std::vector<double>{1, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0,
                                                             0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0});
    const std::vector<bool> mask = interiorMask(renderPlane(quaternion).image);
    EXPECT_EQ(mask, interiorMask(renderPlane(octonion).image));
    EXPECT_GT(std::count(mask.begin(), mask.end(), true), 48 * 32 / 20);
}

TEST(PlaneRender, ComplexKindsInOtherAlgebrasNeedACopyOfCHoldingEveryConstant) {
    // Bicomplex numbers: i^2 = j^2 = -1, k^2 = +1. With c in span{1, i} the julia kinds draw the
    // quaternion picture of the same complex polynomial; with c = 0.3 + 0.5 j too (span{1, j}).
    Scene quaternion = planeScene("julia", kRabbit, 32, 24, 1);
    Scene bicomplex = quaternion;
    setParameter(bicomplex, "fractal.algebra", std::string("bicomplex"));
    EXPECT_EQ(renderPlane(quaternion).image.pixels(), renderPlane(bicomplex).image.pixels());
    setParameter(bicomplex, "fractal.c", std::vector<double>{-0.3, 0, 0.5, 0});
    EXPECT_NO_THROW(validatePlaneScene(bicomplex));
    // k*k is +1 here but -1 in H: the constants k lie in no copy of C, so no restriction.
    setParameter(bicomplex, "fractal.formula", std::string("k*k*z^2 + c"));
    UserError error = thrownError([&] { validatePlaneScene(bicomplex); });
    EXPECT_EQ(error.key(), "plane.kind");
    EXPECT_NE(std::string(error.what()).find("bicomplex"), std::string::npos) << error.what();
    setParameter(bicomplex, "plane.kind", std::string("mandelbrot"));
    EXPECT_EQ(thrownError([&] { validatePlaneScene(bicomplex); }).key(), "plane.kind");
    setParameter(bicomplex, "fractal.formula", std::string("z^2 + c"));
    setParameter(quaternion, "plane.kind", std::string("mandelbrot"));
    EXPECT_EQ(renderPlane(quaternion).image.pixels(), renderPlane(bicomplex).image.pixels());
    // Coquaternions: j^2 = +1, so c = 0.3 + 0.5 j has no restriction; the slice kind draws it.
    Scene coquaternion = planeScene("basins", {-0.3, 0, 0.5, 0}, 16, 12, 1);
    setParameter(coquaternion, "fractal.algebra", std::string("coquaternion"));
    EXPECT_EQ(thrownError([&] { validatePlaneScene(coquaternion); }).key(), "plane.kind");
    setParameter(coquaternion, "plane.kind", std::string("slice"));
    EXPECT_NO_THROW(validatePlaneScene(coquaternion));
    // Octonions: c must lie in the quaternion half; the 8-component plane lies in the 3D slice.
    Scene octonion = planeScene("julia-boundary", {-0.4, 0.6, 0, 0, 0, 0, 0, 0.1}, 16, 12, 1);
    setParameter(octonion, "fractal.algebra", std::string("octonion"));
    EXPECT_EQ(thrownError([&] { validatePlaneScene(octonion); }).key(), "plane.kind");
    setParameter(octonion, "fractal.c", std::vector<double>{-0.4, 0.6, 0, 0, 0, 0, 0, 0});
    EXPECT_NO_THROW(validatePlaneScene(octonion));
    setParameter(octonion, "plane.kind", std::string("slice"));
    EXPECT_NO_THROW(validatePlaneScene(octonion));
    setParameter(octonion, "plane.v", std::vector<double>{0, 0, 0, 1});
    EXPECT_EQ(thrownError([&] { validatePlaneScene(octonion); }).key(), "plane.v");
}

}  // namespace
}  // namespace quaternia
