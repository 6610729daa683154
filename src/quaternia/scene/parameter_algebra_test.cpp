// The table's keys of the other algebras (issue 16): fractal.algebra, fractal.c of 4 or 8
// components, slice.origin and slice.axes, and validateScene's checks of them against each other.
#include <gtest/gtest.h>

#include "quaternia/algebra/test_helpers.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_file.h"
#include "quaternia/scene/scene_fractal.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

using namespace quaternia::testing;

UserError setError(std::string_view name, const ParameterValue& value) {
    Scene scene = defaultScene();
    return thrownError([&] { setParameter(scene, name, value); });
}

// Eight components of c for the 8-component algebras.
const std::vector<double> kEightComponents = {-0.2, 0.6, 0.2, 0.2, 0.1, -0.3, 0.05, 0.4};

// The slice of an octonion scene: the origin and three independent, not orthonormal, axes.
const std::vector<double> kOrigin = {0, 0, 0, 0.5, 0, 0, 0, -0.25};
const std::vector<double> kAxes = {1, 0, 0, 0, 0, 0, 0, 0,  //
                                   1, 1, 0, 0, 0, 0, 0, 0,  //
                                   0, 0, 0, 0, 1, 0, 0, 2};

Scene octonionScene() {
    Scene s = defaultScene();
    setParameter(s, "fractal.algebra", std::string("octonion"));
    setParameter(s, "fractal.c", kEightComponents);
    return s;
}

UserError validateError(const Scene& scene) {
    return thrownError([&] { validateScene(scene); });
}

TEST(ParameterAlgebra, DefaultsToQuaternionRightAfterTheFormula) {
    const Parameter* p = findParameter("fractal.algebra");
    ASSERT_NE(p, nullptr);
    EXPECT_EQ(p->type, ParameterType::Choice);
    EXPECT_EQ(p->defaultValue, ParameterValue(std::string("quaternion")));
    EXPECT_EQ(p->choices, (std::vector<std::string>{"quaternion", "bicomplex", "coquaternion",
                                                    "biquaternion", "octonion"}));
    EXPECT_EQ(p->motion, Motion::Numeric);
    EXPECT_EQ(p - 1, findParameter("fractal.formula"));
    EXPECT_EQ(defaultScene().fractal.algebra, Algebra::kQuaternion);
}

TEST(ParameterAlgebra, AcceptsEveryAlgebraByName) {
    for (Algebra algebra : allAlgebras()) {
        const std::string name(algebraName(algebra));
        SCOPED_TRACE(name);
        Scene s = defaultScene();
        s.fractal.algebra =
            algebra == Algebra::kQuaternion ? Algebra::kOctonion : Algebra::kQuaternion;
        setParameter(s, "fractal.algebra", name);
        EXPECT_EQ(s.fractal.algebra, algebra);
        EXPECT_EQ(findParameter("fractal.algebra")->read(s), ParameterValue(name));
    }
}

TEST(ParameterAlgebra, RejectsAnUnknownAlgebraNamingTheKey) {
    UserError error = setError("fractal.algebra", std::string("sedenion"));
    EXPECT_EQ(error.key(), "fractal.algebra");
    EXPECT_STREQ(error.what(),
                 "fractal.algebra must be \"quaternion\", \"bicomplex\", \"coquaternion\", "
                 "\"biquaternion\" or \"octonion\", got \"sedenion\"");
}

TEST(ParameterConstant, TakesFourOrEightComponents) {
    const Parameter& p = *findParameter("fractal.c");
    EXPECT_EQ(p.type, ParameterType::Components);
    EXPECT_EQ(p.lengths, (std::vector<std::size_t>{4, 8}));
    EXPECT_EQ(describeType(p), "an array of 4 or 8 numbers");
    Scene s = defaultScene();
    EXPECT_EQ(s.fractal.cComponents, 4);
    setParameter(s, "fractal.c", kEightComponents);
    EXPECT_EQ(s.fractal.c, Quaternion(-0.2, 0.6, 0.2, 0.2));
    EXPECT_EQ(s.fractal.cUpper, (std::array<double, 4>{0.1, -0.3, 0.05, 0.4}));
    EXPECT_EQ(s.fractal.cComponents, 8);
    EXPECT_EQ(p.read(s), ParameterValue(kEightComponents));
    // Four again: the upper components are cleared, and four are read back.
    setParameter(s, "fractal.c", std::vector<double>{0.1, 0.2, 0.3, 0.4});
    EXPECT_EQ(s.fractal.cUpper, (std::array<double, 4>{0, 0, 0, 0}));
    EXPECT_EQ(s.fractal.cComponents, 4);
    EXPECT_EQ(p.read(s), ParameterValue(std::vector<double>{0.1, 0.2, 0.3, 0.4}));
}

TEST(ParameterConstant, RejectsOtherLengthsAndComponentsOutOfRange) {
    UserError error = setError("fractal.c", std::vector<double>{1, 2, 3});
    EXPECT_EQ(error.key(), "fractal.c");
    EXPECT_STREQ(error.what(), "fractal.c must be an array of 4 or 8 numbers, got [1.0, 2.0, 3.0]");
    EXPECT_STREQ(setError("fractal.c", std::vector<double>{1, 2, 3, 4, 5}).what(),
                 "fractal.c must be an array of 4 or 8 numbers, got [1.0, 2.0, 3.0, 4.0, 5.0]");
    EXPECT_STREQ(setError("fractal.c", std::vector<double>{}).what(),
                 "fractal.c must be an array of 4 or 8 numbers, got []");
    EXPECT_STREQ(setError("fractal.c", std::vector<double>{0, 0, 0, 0, 0, 0, 11, 0}).what(),
                 "fractal.c[6] = 11.0 is out of range [-10, 10]");
}

TEST(ParameterValidateScene, ChecksTheComponentsOfCAgainstTheAlgebra) {
    Scene s = octonionScene();
    EXPECT_NO_THROW(validateScene(s));
    setParameter(s, "fractal.algebra", std::string("biquaternion"));
    EXPECT_NO_THROW(validateScene(s));

    setParameter(s, "fractal.algebra", std::string("quaternion"));
    UserError error = validateError(s);
    EXPECT_EQ(error.key(), "fractal.c");
    EXPECT_STREQ(error.what(), "fractal.c has 8 components; the quaternion algebra has 4");

    // A shorter c is filled with zeros: the default c is an octonion's and a biquaternion's.
    s = defaultScene();
    for (const char* algebra : {"octonion", "biquaternion"}) {
        setParameter(s, "fractal.algebra", std::string(algebra));
        EXPECT_NO_THROW(validateScene(s)) << algebra;
        const std::vector<double> c = cComponents(s);
        EXPECT_EQ(c, (std::vector<double>{-0.2, 0.6, 0.2, 0.2, 0, 0, 0, 0})) << algebra;
    }

    for (const char* algebra : {"bicomplex", "coquaternion"}) {
        setParameter(s, "fractal.algebra", std::string(algebra));
        EXPECT_NO_THROW(validateScene(s)) << algebra;
    }
}

TEST(ParameterSlice, TakesOriginAndAxesOfTheirLengths) {
    const Parameter& origin = *findParameter("slice.origin");
    const Parameter& axes = *findParameter("slice.axes");
    EXPECT_EQ(origin.defaultValue, ParameterValue(std::vector<double>{}));
    EXPECT_EQ(axes.defaultValue, ParameterValue(std::vector<double>{}));
    EXPECT_EQ(describeType(origin), "an empty array or an array of 4 or 8 numbers");
    EXPECT_EQ(describeType(axes),
              "an empty array or an array of 12 or 24 numbers (or 3 arrays of 4 or 8)");
    Scene s = octonionScene();
    setParameter(s, "slice.origin", kOrigin);
    setParameter(s, "slice.axes", kAxes);
    EXPECT_EQ(s.slice.origin, kOrigin);
    EXPECT_EQ(s.slice.axes, kAxes);
    EXPECT_NO_THROW(validateScene(s));
    setParameter(s, "slice.axes", std::vector<double>{});
    EXPECT_TRUE(s.slice.axes.empty());

    UserError error = setError("slice.origin", std::vector<double>{1, 2, 3});
    EXPECT_EQ(error.key(), "slice.origin");
    EXPECT_STREQ(error.what(),
                 "slice.origin must be an empty array or an array of 4 or 8 numbers, got [1.0, "
                 "2.0, 3.0]");
    error = setError("slice.axes", std::vector<double>(8, 1.0));
    EXPECT_EQ(error.key(), "slice.axes");
    EXPECT_EQ(std::string(error.what())
                  .rfind("slice.axes must be an empty array or an array of 12 or 24 numbers "
                         "(or 3 arrays of 4 or 8), got [1.0, ",
                         0),
              0u)
        << error.what();
    std::vector<double> far = kAxes;
    far[23] = 1001;
    EXPECT_STREQ(setError("slice.axes", far).what(),
                 "slice.axes[23] = 1001.0 is out of range [-1000, 1000]");
}

TEST(ParameterValidateScene, RejectsOriginAndAxesForTheFourComponentAlgebras) {
    for (const char* algebra : {"quaternion", "bicomplex", "coquaternion"}) {
        SCOPED_TRACE(algebra);
        Scene s = defaultScene();
        setParameter(s, "fractal.algebra", std::string(algebra));
        setParameter(s, "slice.origin", kOrigin);
        UserError error = validateError(s);
        EXPECT_EQ(error.key(), "slice.origin");
        EXPECT_EQ(std::string(error.what()),
                  "slice.origin is for the 8-component algebras (biquaternion, octonion); " +
                      std::string(algebra) +
                      " slices are set by slice.normal, slice.distance, slice.left, slice.right "
                      "and slice.angles");
        setParameter(s, "slice.origin", std::vector<double>{});
        setParameter(s, "slice.axes", kAxes);
        error = validateError(s);
        EXPECT_EQ(error.key(), "slice.axes");
        EXPECT_EQ(std::string(error.what()).rfind("slice.axes is for the 8-component algebras", 0),
                  0u)
            << error.what();
    }
    Scene s = defaultScene();
    setParameter(s, "slice.axes", kAxes);
    EXPECT_STREQ(validateError(s).what(),
                 "slice.axes is for the 8-component algebras (biquaternion, octonion); quaternion "
                 "slices are set by slice.normal, slice.distance, slice.left, slice.right and "
                 "slice.angles");
}

TEST(ParameterValidateScene, RejectsQuaternionSliceKeysForTheEightComponentAlgebras) {
    const std::pair<const char*, ParameterValue> changes[] = {
        {"slice.normal", std::vector<double>{0, 0, 1, 1}},
        {"slice.distance", 0.5},
        {"slice.left", std::vector<double>{0, 1, 0, 0}},
        {"slice.right", std::vector<double>{0, 0, 1, 0}},
        {"slice.angles", std::vector<double>{0, 0, 0, 0, 0, 30}}};
    for (const auto& [name, value] : changes) {
        SCOPED_TRACE(name);
        Scene s = octonionScene();
        setParameter(s, name, value);
        UserError error = validateError(s);
        EXPECT_EQ(error.key(), name);
        EXPECT_EQ(std::string(error.what()),
                  std::string(name) +
                      " applies to the 4-component algebras; the octonion algebra takes "
                      "slice.origin and slice.axes");
    }
    Scene s = octonionScene();
    setParameter(s, "fractal.algebra", std::string("biquaternion"));
    setParameter(s, "slice.normal", std::vector<double>{0, 0, 1, 1});
    EXPECT_STREQ(validateError(s).what(),
                 "slice.normal applies to the 4-component algebras; the biquaternion algebra "
                 "takes slice.origin and slice.axes");
}

TEST(ParameterValidateScene, RejectsDegenerateSliceAxes) {
    auto axesError = [](std::vector<double> axes) {
        Scene s = octonionScene();
        setParameter(s, "slice.axes", axes);
        return validateError(s);
    };
    std::vector<double> axes = kAxes;
    for (int k = 0; k < 8; ++k)
        axes[8 + k] = -2 * axes[k];  // axis 2 parallel to axis 1
    UserError error = axesError(axes);
    EXPECT_EQ(error.key(), "slice.axes");
    EXPECT_STREQ(error.what(),
                 "slice.axes: axis 2 lies in the span of the axes before it; three independent "
                 "directions are needed");
    axes = kAxes;
    for (int k = 0; k < 8; ++k)
        axes[16 + k] = 3 * axes[k] - 0.5 * axes[8 + k];  // axis 3 in the plane of 1 and 2
    EXPECT_STREQ(axesError(axes).what(),
                 "slice.axes: axis 3 lies in the span of the axes before it; three independent "
                 "directions are needed");
    axes = kAxes;
    std::fill(axes.begin(), axes.begin() + 8, 0.0);
    error = axesError(axes);
    EXPECT_EQ(error.key(), "slice.axes");
    EXPECT_STREQ(error.what(),
                 "slice.axes: axis 1 is zero; three independent directions are needed");
    // Short axes are fine: only directions count.
    axes = kAxes;
    for (double& x : axes)
        x *= 1e-6;
    Scene s = octonionScene();
    setParameter(s, "slice.axes", axes);
    EXPECT_NO_THROW(validateScene(s));
}

TEST(ParameterHelp, DescribesTheAlgebraAndTheComponentsOfC) {
    std::string help = parameterHelp();
    EXPECT_NE(help.find("  fractal.algebra = \"quaternion\"    (choice, \"quaternion\", "
                        "\"bicomplex\", \"coquaternion\", \"biquaternion\" or \"octonion\")"),
              std::string::npos)
        << help;
    EXPECT_NE(help.find("  fractal.c = [-0.2, 0.6, 0.2, 0.2]    (4 or 8 reals, each in [-10, 10])"),
              std::string::npos);
    EXPECT_NE(help.find("  slice.axes = []    (empty, 12 or 24 reals, each in [-1000, 1000])"),
              std::string::npos);
    EXPECT_LT(help.find("fractal.formula ="), help.find("fractal.algebra ="));
    EXPECT_LT(help.find("fractal.algebra ="), help.find("fractal.c ="));
}

}  // namespace
}  // namespace quaternia

namespace quaternia {
namespace {

// slice.origin of 4 components is the 8-component origin with zeros after them.
TEST(ParameterValidateScene, AShorterSliceOriginIsFilledWithZeros) {
    Scene shorter = defaultScene(), full = defaultScene();
    for (Scene* s : {&shorter, &full})
        setParameter(*s, "fractal.algebra", std::string("octonion"));
    setParameter(shorter, "slice.origin", std::vector<double>{0, 0, 0, 0.3});
    setParameter(full, "slice.origin", std::vector<double>{0, 0, 0, 0.3, 0, 0, 0, 0});
    EXPECT_NO_THROW(validateScene(shorter));
    const Hypercomplex a = fractalFromScene(shorter).slice().fromWorld(Point3d(0.1, 0.2, 0.3));
    const Hypercomplex b = fractalFromScene(full).slice().fromWorld(Point3d(0.1, 0.2, 0.3));
    EXPECT_EQ(a, b);
    EXPECT_EQ(a[3], 0.3);
}

// slice.axes of 4 components each (12 numbers, or three arrays of 4 in a scene file) are the
// same directions with components 4 .. 7 zero; their independence is checked alike.
TEST(ParameterValidateScene, ShorterSliceAxesAreFilledWithZeros) {
    Scene shorter = parseScene(
        "[fractal]\nalgebra = \"biquaternion\"\n[slice]\n"
        "axes = [[0, 1, 0, 0], [0, 0, 1, 0.5], [0, 0, 0, 1]]\n");
    EXPECT_EQ(shorter.slice.axes.size(), 12u);
    EXPECT_NO_THROW(validateScene(shorter));
    Scene full = shorter;
    setParameter(full, "slice.axes",
                 std::vector<double>{0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0.5, 0, 0, 0, 0,  //
                                     0, 0, 0, 1, 0, 0, 0, 0});
    for (const Point3d p : {Point3d(0.1, 0.2, 0.3), Point3d(-1, 0.5, 2)})
        EXPECT_EQ(fractalFromScene(shorter).slice().fromWorld(p),
                  fractalFromScene(full).slice().fromWorld(p));
    // Written back as three arrays of 4.
    EXPECT_NE(sceneToToml(shorter).find("axes = [[0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.5], "),
              std::string::npos)
        << sceneToToml(shorter);
    setParameter(shorter, "slice.axes",
                 std::vector<double>{0, 1, 0, 0, 0, 0, 1, 0, 0, 2, 0, 0});  // axis 3 = 2 axis 1
    try {
        validateScene(shorter);
        ADD_FAILURE() << "dependent axes accepted";
    } catch (const UserError& e) {
        EXPECT_EQ(e.key(), "slice.axes");
    }
}

}  // namespace
}  // namespace quaternia
