#include "quaternia/scene/parameters.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include <gtest/gtest.h>

#include "quaternia/algebra/test_helpers.h"
#include "quaternia/scene/parameter_text.h"
#include "quaternia/util/edit_distance.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

using namespace quaternia::testing;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInfinity = std::numeric_limits<double>::infinity();

UserError setError(std::string_view name, const ParameterValue& value) {
    Scene scene = defaultScene();
    return thrownError([&] { setParameter(scene, name, value); });
}

// A valid value other than the default, to see which field a parameter writes.
ParameterValue alternativeValue(const Parameter& p) {
    switch (p.type) {
        case ParameterType::Real: {
            double x = std::get<double>(p.defaultValue);
            return x == p.maximum ? p.minimum : p.maximum;
        }
        case ParameterType::Integer: {
            if (!p.allowedIntegers.empty())
                return p.allowedIntegers.front() == std::get<int64_t>(p.defaultValue)
                           ? p.allowedIntegers.back()
                           : p.allowedIntegers.front();
            int64_t n = std::get<int64_t>(p.defaultValue);
            return n == int64_t(p.maximum) ? int64_t(p.minimum) : int64_t(p.maximum);
        }
        case ParameterType::Boolean:
            return !std::get<bool>(p.defaultValue);
        case ParameterType::Text:
            return std::get<std::string>(p.defaultValue) + " + z";
        case ParameterType::Choice:
            return p.choices.front() == std::get<std::string>(p.defaultValue) ? p.choices.back()
                                                                              : p.choices.front();
        case ParameterType::Components:
            // slice.origin and slice.axes default to the empty array: the longest length.
            if (std::get<std::vector<double>>(p.defaultValue).empty())
                return std::vector<double>(p.lengths.back(), p.maximum / 2);
            [[fallthrough]];
        default: {
            auto v = std::get<std::vector<double>>(p.defaultValue);
            for (double& x : v)
                x = x == p.maximum ? p.minimum : (x + p.maximum) / 2;
            return v;
        }
    }
}

TEST(ParameterTable, HasEveryKeyOnceGroupedBySection) {
    const auto& table = parameterTable();
    EXPECT_EQ(table.size(), 197u);  // every field of Scene (scene.h) but the animation keys
    std::set<std::string> names;
    for (const auto& p : table) {
        EXPECT_TRUE(names.insert(p.name()).second) << p.name() << " is declared twice";
        EXPECT_EQ(findParameter(p.name()), &p);
        EXPECT_FALSE(p.help.empty()) << p.name();
    }
    EXPECT_EQ(parameterSections(),
              (std::vector<std::string>{"fractal", "slice",  "camera",   "render", "shading",
                                        "light1",  "light2", "light3",   "light4", "light5",
                                        "light6",  "light7", "material", "ground", "environment",
                                        "plane",   "mesh",   "orbit",    "cycles", "animation"}));
    EXPECT_EQ(table.front().name(), "fractal.formula");
    EXPECT_EQ(table.back().name(), "animation.c_radius");
    EXPECT_EQ(findParameter("render"), nullptr);
    EXPECT_EQ(findParameter("render.widt"), nullptr);
    EXPECT_EQ(findParameter("render.width.x"), nullptr);
}

TEST(ParameterTable, DefaultsLieInRangeAndRoundTripThroughTheScene) {
    for (const auto& p : parameterTable()) {
        SCOPED_TRACE(p.name());
        ParameterValue checked;
        EXPECT_NO_THROW(checked = checkedValue(p, p.defaultValue));
        EXPECT_EQ(checked, p.defaultValue);
        Scene scene;
        p.apply(scene, p.defaultValue);
        EXPECT_EQ(p.read(scene), p.defaultValue);
    }
}

TEST(ParameterTable, EachParameterWritesOnlyItsOwnField) {
    const auto& table = parameterTable();
    for (const auto& p : table) {
        SCOPED_TRACE(p.name());
        Scene scene = defaultScene();
        ParameterValue value = alternativeValue(p);
        ASSERT_NE(value, p.defaultValue);
        setParameter(scene, p.name(), value);
        EXPECT_EQ(p.read(scene), value);
        for (const auto& other : table) {
            if (&other == &p) continue;
            EXPECT_EQ(other.read(scene), other.defaultValue) << other.name();
        }
    }
}

TEST(ParameterDefaults, MatchesTheTable) {
    Scene s = defaultScene();
    EXPECT_EQ(s.fractal.formula, "z^2 + c");
    EXPECT_EQ(s.fractal.c, Quaternion(-0.2, 0.6, 0.2, 0.2));
    EXPECT_EQ(s.fractal.maxIterations, 12);
    EXPECT_EQ(s.fractal.bailout, 0.0);

    EXPECT_EQ(s.slice.normal, Quaternion(0, 0, 0, 1));  // (x, y, z, w): w is the 4th
    EXPECT_EQ(s.slice.distance, 0.0);
    EXPECT_EQ(s.slice.left, Quaternion(1, 0, 0, 0));
    EXPECT_EQ(s.slice.right, Quaternion(1, 0, 0, 0));
    EXPECT_EQ(s.slice.anglesDegrees, (std::array<double, 6>{0, 0, 0, 0, 0, 0}));

    EXPECT_EQ(s.camera.position, Point3d(1.25, 1.875, -5));
    EXPECT_EQ(s.camera.lookAt, Point3d(0, 0, 0));
    EXPECT_EQ(s.camera.up, Vector3d(0, 1, 0));
    EXPECT_EQ(s.camera.fovDegrees, 45.0);

    EXPECT_EQ(s.render.width, 1280);
    EXPECT_EQ(s.render.height, 720);
    EXPECT_EQ(s.render.samples, 4);
    EXPECT_EQ(s.render.method, MarchMethod::SphereTracing);
    EXPECT_EQ(s.render.step, 0.002);
    EXPECT_EQ(s.render.epsilon, 0.25);
    EXPECT_EQ(s.render.maxSteps, 5000);
    EXPECT_EQ(s.render.bitDepth, 8);
    EXPECT_EQ(s.render.alpha, AlphaMode::Coverage);

    const ShadingSettings& h = s.shading;
    EXPECT_EQ(h.lightDirection, Vector3d(-0.5, 0.8, -0.6));
    EXPECT_EQ(h.lightColor, Color(1.0, 0.92, 0.8));
    EXPECT_EQ(h.shadows, Shadows::Soft);
    EXPECT_EQ(h.shadowSoftness, 12.0);
    EXPECT_EQ(h.fillDirection, Vector3d(0.6, 0.2, -0.4));
    EXPECT_EQ(h.fillColor, Color(0.12, 0.16, 0.25));
    EXPECT_EQ(h.ambient, 0.08);
    EXPECT_EQ(h.ambientOcclusion, 0.8);
    EXPECT_EQ(h.specular, 0.3);
    EXPECT_EQ(h.shininess, 40.0);
    EXPECT_EQ(h.coloring, Coloring::OrbitTrap);
    EXPECT_EQ(h.baseColor, Color(0.85, 0.42, 0.1));
    EXPECT_EQ(h.accentColor, Color(0.04, 0.16, 0.45));
    EXPECT_EQ(h.backgroundTop, Color(0.02, 0.025, 0.04));
    EXPECT_EQ(h.backgroundBottom, Color(0.002, 0.002, 0.004));
    EXPECT_EQ(h.gamma, 2.2);
    EXPECT_EQ(h.exposure, 1.0);

    EXPECT_EQ(s.orbit.z0, Quaternion(0, 0, 0, 0));
    EXPECT_EQ(s.orbit.maxIterations, 1000);
    EXPECT_EQ(s.cycles.period, 1);

    EXPECT_NO_THROW(validateScene(s));
}

TEST(ParameterSet, AppliesValuesToTheirFields) {
    Scene s = defaultScene();
    setParameter(s, "render.width", int64_t{640});
    setParameter(s, "render.method", std::string("fixed-step"));
    setParameter(s, "shading.shadows", std::string("none"));
    setParameter(s, "shading.coloring", std::string("iteration"));
    setParameter(s, "fractal.c", std::vector<double>{0.1, 0.2, 0.3, 0.4});
    setParameter(s, "slice.normal", std::vector<double>{0.2, -0.3, 0.4, 1});
    setParameter(s, "slice.angles", std::vector<double>{1, 2, 3, 4, 5, 6});
    setParameter(s, "camera.position", std::vector<double>{7, 8, 9});
    EXPECT_EQ(s.render.width, 640);
    EXPECT_EQ(s.render.method, MarchMethod::FixedStep);
    EXPECT_EQ(s.shading.shadows, Shadows::None);
    EXPECT_EQ(s.shading.coloring, Coloring::Iteration);
    EXPECT_EQ(s.fractal.c, Quaternion(0.1, 0.2, 0.3, 0.4));  // (1, i, j, k) = (w, x, y, z)
    // The normal's components in order: its w (POV-Ray's 4th) lands in the k slot.
    EXPECT_EQ(s.slice.normal, Quaternion(0.2, -0.3, 0.4, 1));
    EXPECT_EQ(s.slice.anglesDegrees, (std::array<double, 6>{1, 2, 3, 4, 5, 6}));
    EXPECT_EQ(s.camera.position, Point3d(7, 8, 9));
}

TEST(ParameterSet, AcceptsAnIntegerForAReal) {
    Scene s = defaultScene();
    setParameter(s, "camera.fov", int64_t{60});
    EXPECT_EQ(s.camera.fovDegrees, 60.0);
    EXPECT_EQ(findParameter("camera.fov")->read(s), ParameterValue(60.0));
}

TEST(ParameterSet, AcceptsAnIntegralRealForAnInteger) {
    Scene s = defaultScene();
    setParameter(s, "render.width", 640.0);
    EXPECT_EQ(s.render.width, 640);
    UserError error = setError("render.width", 640.5);
    EXPECT_EQ(error.key(), "render.width");
    EXPECT_STREQ(error.what(), "render.width must be an integer, got 640.5");
}

TEST(ParameterSet, RejectsAnUnknownKeyWithTheNearestOne) {
    UserError error = setError("render.widht", int64_t{640});
    EXPECT_EQ(error.key(), "render.widht");
    EXPECT_STREQ(error.what(), "unknown key 'render.widht' (did you mean 'render.width'?)");
}

TEST(ParameterSet, RejectsAWrongType) {
    UserError error = setError("render.width", std::string("abc"));
    EXPECT_EQ(error.key(), "render.width");
    EXPECT_STREQ(error.what(), "render.width must be an integer, got \"abc\"");
    EXPECT_STREQ(setError("camera.fov", true).what(), "camera.fov must be a number, got true");
    EXPECT_STREQ(setError("fractal.formula", 2.0).what(),
                 "fractal.formula must be a string, got 2.0");
    EXPECT_STREQ(setError("camera.up", 1.0).what(),
                 "camera.up must be an array of 3 numbers, got 1.0");
}

TEST(ParameterSet, RejectsNaNAndInfinity) {
    UserError error = setError("render.step", kNaN);
    EXPECT_EQ(error.key(), "render.step");
    EXPECT_STREQ(error.what(), "render.step must be finite, got nan");
    EXPECT_STREQ(setError("render.width", -kInfinity).what(),
                 "render.width must be finite, got -inf");
    error = setError("camera.position", std::vector<double>{0, kInfinity, 1});
    EXPECT_EQ(error.key(), "camera.position");
    EXPECT_STREQ(error.what(), "camera.position must be finite, got [0.0, inf, 1.0]");
}

TEST(ParameterSet, RejectsValuesOutOfRange) {
    UserError error = setError("render.width", int64_t{0});
    EXPECT_EQ(error.key(), "render.width");
    EXPECT_STREQ(error.what(), "render.width = 0 is out of range [1, 16384]");
    EXPECT_STREQ(setError("render.epsilon", 20.0).what(),
                 "render.epsilon = 20.0 is out of range [0.0001, 10]");
    EXPECT_STREQ(setError("render.step", 0.0).what(),
                 "render.step = 0.0 is out of range [0.000001, 1]");
    error = setError("camera.position", std::vector<double>{0, 0, 2e4});
    EXPECT_EQ(error.key(), "camera.position");
    EXPECT_STREQ(error.what(), "camera.position[2] = 20000.0 is out of range [-10000, 10000]");
    // The ends of a range are allowed.
    Scene s = defaultScene();
    EXPECT_NO_THROW(setParameter(s, "render.width", int64_t{16384}));
    EXPECT_NO_THROW(setParameter(s, "camera.fov", 179.0));
}

TEST(ParameterSet, RejectsAVectorOfTheWrongLength) {
    UserError error = setError("fractal.c", std::vector<double>{1, 2});
    EXPECT_EQ(error.key(), "fractal.c");
    EXPECT_STREQ(error.what(), "fractal.c must be an array of 4 or 8 numbers, got [1.0, 2.0]");
    EXPECT_STREQ(setError("slice.angles", std::vector<double>{1, 2, 3}).what(),
                 "slice.angles must be an array of 6 numbers, got [1.0, 2.0, 3.0]");
}

TEST(ParameterSet, RejectsAWordThatIsNotAChoice) {
    UserError error = setError("render.method", std::string("spherical"));
    EXPECT_EQ(error.key(), "render.method");
    EXPECT_STREQ(error.what(),
                 "render.method must be \"sphere\" or \"fixed-step\", got \"spherical\"");
    EXPECT_STREQ(setError("shading.shadows", int64_t{1}).what(),
                 "shading.shadows must be \"soft\", \"hard\" or \"none\", got 1");
}

TEST(ParameterSet, AllowsOnlyBitDepths8And16) {
    UserError error = setError("render.bit_depth", int64_t{12});
    EXPECT_EQ(error.key(), "render.bit_depth");
    EXPECT_STREQ(error.what(), "render.bit_depth = 12 is not allowed; use 8 or 16");
    Scene s = defaultScene();
    setParameter(s, "render.bit_depth", int64_t{16});
    EXPECT_EQ(s.render.bitDepth, 16);
}

TEST(ParameterSet, RejectsEmptyAndOverlongText) {
    EXPECT_STREQ(setError("fractal.formula", std::string()).what(),
                 "fractal.formula must not be empty");
    EXPECT_STREQ(setError("fractal.formula", std::string(1001, 'z')).what(),
                 "fractal.formula has 1001 characters; at most 1000 are allowed");
}

// Scene files are TOML, whose strings are UTF-8: text that is not, or that holds control
// characters, would be written into a file that does not read back (found by fuzzing).
TEST(ParameterSet, RejectsTextThatIsNotUtf8OrHasControlCharacters) {
    for (const std::string& bad :
         {std::string("z^2 + \xb0"), std::string("z^2\xc0\x80"), std::string("\xed\xa0\x80"),
          std::string("z\xf4\x90\x80\x80"), std::string("z^2 + c\n"), std::string("z\x04"),
          std::string("z\x7f"), std::string("z\0", 2)}) {
        UserError error = setError("fractal.formula", bad);
        EXPECT_EQ(error.key(), "fractal.formula");
    }
    EXPECT_STREQ(setError("fractal.formula", std::string("z^2 \xb0")).what(),
                 "fractal.formula is not valid UTF-8 (byte 5)");
    EXPECT_STREQ(setError("fractal.formula", std::string("z\t\r")).what(),
                 "fractal.formula contains a control character (byte 3)");
    Scene s = defaultScene();
    setParameter(s, "fractal.formula", std::string("z^2\t+ c"));  // a tab is white space
    setParameter(s, "fractal.formula", std::string("z^2 + c \xc3\xa9\xe2\x82\xac\xf0\x9f\x98\x80"));
    EXPECT_EQ(s.fractal.formula, "z^2 + c \xc3\xa9\xe2\x82\xac\xf0\x9f\x98\x80");
}

TEST(ParameterSet, LeavesTheSceneUnchangedWhenItThrows) {
    Scene s = defaultScene();
    EXPECT_THROW(setParameter(s, "fractal.c", std::vector<double>{1, 2, 3, 99}), UserError);
    EXPECT_EQ(s.fractal.c, defaultScene().fractal.c);
}

// Past 40 bytes a name is no typo; comparing all of it would cost its length times each name's.
TEST(ParameterNearestName, ComparesOnlyTheFirst40Bytes) {
    const std::string typo = "render.widht" + std::string(28, 'x');
    EXPECT_EQ(nearestParameterName(typo + std::string(100000, 'y')), nearestParameterName(typo));
    EXPECT_EQ(nearestSectionName("shadin" + std::string(100000, 'g')),
              nearestSectionName("shadin" + std::string(34, 'g')));
    for (const Parameter& p : parameterTable())
        EXPECT_LE(p.name().size(), 30u) << p.name();
}

TEST(ParameterNearestName, SuggestsTheClosestName) {
    EXPECT_EQ(nearestParameterName("render.widht"), "render.width");
    EXPECT_EQ(nearestParameterName("camera.fov_deg"), "camera.fov");
    EXPECT_EQ(nearestParameterName("rendr.width"), "render.width");
    EXPECT_EQ(nearestParameterName("width"), "render.width");
    EXPECT_EQ(nearestParameterName("image.height"), "render.height");
    EXPECT_EQ(nearestParameterName("shading.colouring"), "shading.coloring");
    EXPECT_EQ(nearestParameterName("fractal.max_iteration"), "fractal.max_iterations");
    EXPECT_EQ(nearestParameterName("camera.lookat"), "camera.look_at");
    // Within a known section its own keys come first, and a typed beginning counts.
    EXPECT_EQ(nearestParameterName("fractal.max_iter"), "fractal.max_iterations");
    EXPECT_EQ(nearestParameterName("shading.light"), "shading.light_kind");
    EXPECT_EQ(nearestParameterName("render.sample"), "render.samples");
    // A key of another section: "shading.width" is nearer "shading.gamma" letter by letter.
    EXPECT_EQ(nearestParameterName("shading.width"), "render.width");
    EXPECT_EQ(nearestParameterName("colouring"), "shading.coloring");
    EXPECT_EQ(nearestSectionName("rendr"), "render");
    EXPECT_EQ(nearestSectionName("shade"), "shading");
}

// nearestParameterName computes each distance only up to the best so far; with the whole
// distances (editDistance without a bound) and the rule its comments state it must choose the
// same names.
std::string nearestByWholeDistances(std::string_view name) {
    name = name.substr(0, 40);
    const size_t dot = name.find('.');
    const std::string_view section = dot == std::string_view::npos ? "" : name.substr(0, dot);
    const std::string_view key = dot == std::string_view::npos ? name : name.substr(dot + 1);
    const auto& sections = parameterSections();
    const bool known = std::find(sections.begin(), sections.end(), section) != sections.end();
    std::string best;
    size_t bestDistance = SIZE_MAX, bestPrefix = 0;
    for (const Parameter& p : parameterTable()) {
        size_t keyDistance = editDistance(key, p.key);
        if (key.size() >= 3 && p.key.starts_with(key))
            keyDistance = std::min<size_t>(keyDistance, 1);
        const size_t sectionCost = section == p.section ? 0 : known ? 2 : 1;
        const std::string candidate = p.name();
        const size_t distance = std::min(editDistance(name, candidate), keyDistance + sectionCost);
        size_t prefix = 0;
        while (prefix < name.size() && prefix < candidate.size() &&
               name[prefix] == candidate[prefix])
            ++prefix;
        if (distance < bestDistance || (distance == bestDistance && prefix > bestPrefix))
            best = candidate, bestDistance = distance, bestPrefix = prefix;
    }
    return best;
}

TEST(ParameterNearestName, AgreesWithTheWholeDistances) {
    std::vector<std::string> names = {"",
                                      "x",
                                      "render",
                                      "render.",
                                      ".width",
                                      "widht",
                                      "camera.fov_deg",
                                      "slice.w",
                                      "fractal.c.x",
                                      std::string(60, 'q')};
    for (const Parameter& p : parameterTable()) {
        const std::string n = p.name();
        names.push_back(n);
        names.push_back(n.substr(0, n.size() / 2));
        names.push_back(n.substr(n.size() / 3));
        names.push_back(n + "s");
        names.push_back(std::string(n.rbegin(), n.rend()));
        names.push_back(p.key);
        names.push_back("shading." + p.key);
    }
    for (const std::string& name : names)
        EXPECT_EQ(nearestParameterName(name), nearestByWholeDistances(name)) << name;
}

TEST(ParameterFormatValue, WritesTomlThatReadsBackExactly) {
    EXPECT_EQ(formatValue(1.0), "1.0");
    EXPECT_EQ(formatValue(-4.0), "-4.0");
    EXPECT_EQ(formatValue(0.1), "0.1");
    EXPECT_EQ(formatValue(0.1 + 0.2), "0.30000000000000004");
    EXPECT_EQ(formatValue(1e6), "1e+06");
    EXPECT_EQ(formatValue(1e-300), "1e-300");
    EXPECT_EQ(formatValue(kNaN), "nan");
    EXPECT_EQ(formatValue(-kInfinity), "-inf");
    EXPECT_EQ(formatValue(int64_t{-640}), "-640");
    EXPECT_EQ(formatValue(false), "false");
    EXPECT_EQ(formatValue(std::string("a \"b\" \\ c\n")), "\"a \\\"b\\\" \\\\ c\\n\"");
    EXPECT_EQ(formatValue(std::string("\x01")), "\"\\u0001\"");
    EXPECT_EQ(formatValue(std::vector<double>{0, 1.5, -4}), "[0.0, 1.5, -4.0]");
    EXPECT_EQ(formatValue(std::vector<double>{}), "[]");
}

TEST(ParameterHelp, ListsEveryKeyWithItsDefaultRangeAndHelp) {
    std::string help = parameterHelp();
    for (const auto& p : parameterTable()) {
        SCOPED_TRACE(p.name());
        // [light2] .. [light7] repeat [light1]'s keys: named once, as a range.
        if (p.section.rfind("light", 0) == 0 && p.section != "light1") {
            EXPECT_EQ(help.find("  " + p.name() + " ="), std::string::npos);
            continue;
        }
        EXPECT_NE(help.find("  " + p.name() + " = " + formatValue(p.defaultValue)),
                  std::string::npos);
        EXPECT_NE(help.find(describeRange(p)), std::string::npos);
        EXPECT_NE(help.find(p.help), std::string::npos);
    }
    EXPECT_NE(help.find("render.width = 1280    (integer, [1, 16384])"), std::string::npos);
    EXPECT_NE(help.find("[light2] .. [light7]\n  The same keys as [light1]"), std::string::npos);
    EXPECT_NE(help.find("render.method = \"sphere\"    (choice, \"sphere\" or \"fixed-step\")"),
              std::string::npos);
    EXPECT_NE(help.find("\n[shading]\n"), std::string::npos);
}

// docs/parameters.md (ctest's Docs.ParameterReferenceIsCurrent compares the committed file): a
// row of every key, its default and range, under its section's heading, which the list at the
// top links; [light2] .. [light7] named once, as in --help.
TEST(ParameterReference, HasARowOfEveryKeyUnderItsSection) {
    const std::string reference = parameterReference();
    for (const auto& p : parameterTable()) {
        SCOPED_TRACE(p.name());
        if (p.section.rfind("light", 0) == 0 && p.section != "light1") {
            EXPECT_EQ(reference.find("| `" + p.name() + "` |"), std::string::npos);
            continue;
        }
        const std::size_t row = reference.find("| `" + p.name() + "` | ");
        ASSERT_NE(row, std::string::npos);
        EXPECT_LT(reference.rfind("\n## [" + p.section + "]\n", row), row);
        EXPECT_NE(reference.find("[" + p.section + "](#" + p.section + ")"), std::string::npos);
    }
    EXPECT_NE(reference.find("| `render.width` | integer | `1280` | [1, 16384] | "),
              std::string::npos);
    EXPECT_NE(reference.find("\n## [light2] .. [light7]\n"), std::string::npos);
    EXPECT_NE(reference.find("[light2 .. light7](#light2--light7)"), std::string::npos);
}

// A table cell ends at '|', even in a code span, and "i*z*j*z" outside one would turn italic.
TEST(ParameterReference, EscapesWhatWouldBreakATableCell) {
    EXPECT_EQ(parameter_text::markdownCell("|z| > 2, i*z*j*z, z <- p(z), `a*b|c`"),
              "\\|z\\| > 2, i\\*z\\*j\\*z, z &lt;- p(z), `a*b\\|c`");
    EXPECT_EQ(parameter_text::markdownCode("\"a|b\""), "`\"a\\|b\"`");
    const std::string reference = parameterReference();
    EXPECT_NE(reference.find("A point escapes once \\|z\\| > bailout"), std::string::npos);
    EXPECT_NE(reference.find("\"i\\*z\\*j\\*z + c\""), std::string::npos);
}

// ---- Issue 16: the algebra, c of 4 or 8 components, the slice of the 8-component algebras ----

}  // namespace
}  // namespace quaternia
