// The parameter table: every scene setting declared once, with its name, type, default, range
// and help. The scene file, --set overrides, --help, validation and the live
// explorer's controls are all driven from this one table, so a new setting is one line in
// parameter_table*.cpp (its section's function) and nowhere else.
//
// Names are "section.key", e.g. "render.width". Values travel as ParameterValue; setParameter
// validates a value (type, finiteness, range, choices) before it touches the Scene, so a Scene
// built only through the table is always in range. Cross-field checks (a camera looking at its
// own position, a slice normal without a w component) are validateScene's.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "quaternia/scene/scene.h"

namespace quaternia {

enum class ParameterType {
    Real,
    Integer,
    Boolean,
    Text,
    Choice,
    Vector2,
    Vector3,
    Vector4,
    Vector6,
    // An array of reals whose allowed lengths are Parameter::lengths (fractal.c: 4 or 8;
    // slice.origin: 0 or 8, empty meaning "not given").
    Components
};

struct Parameter {
    std::string section, key;
    std::string name() const { return section + "." + key; }

    ParameterType type = ParameterType::Real;
    // Canonical for the type: double for Real, int64_t for Integer, bool, std::string for Text
    // and Choice, std::vector<double> of the right length for vectors and components.
    ParameterValue defaultValue;
    // Inclusive bounds: of the value (Real, Integer), of each component (vectors), or of the
    // length in characters (Text). Unused for Boolean and Choice.
    double minimum = 0, maximum = 0;
    std::vector<std::string> choices;      // Choice: the allowed words, in display order
    std::vector<int64_t> allowedIntegers;  // Integer: if not empty, the only allowed values
    // Components: the allowed numbers of components, ascending (0: the empty array).
    std::vector<std::size_t> lengths;
    // Components: if not 0, scene files and --set may also write the value as this many arrays
    // of equal length (slice.axes: three arrays of 4 or 8), which are read one after the other.
    std::size_t groups = 0;
    std::string help;                 // one line, for --help, scene files and tooltips
    Motion motion = Motion::Numeric;  // how an animation moves it between keys

    // apply expects a canonical, checked value (see checkedValue); read returns one.
    std::function<void(Scene&, const ParameterValue&)> apply;
    std::function<ParameterValue(const Scene&)> read;
};

// Every parameter, grouped by section in the order fractal, slice, camera, render, shading,
// light1 .. light7, material, ground, plane, mesh, orbit, cycles, animation.
// Builds the table (parameter_table.cpp); everything else reads it through parameterTable().
std::vector<Parameter> buildParameterTable();

const std::vector<Parameter>& parameterTable();
// The sections in table order.
const std::vector<std::string>& parameterSections();
// nullptr if `name` ("section.key") is not in the table.
const Parameter* findParameter(std::string_view name);

// The table name closest to `name`, comparing both the whole name and the key alone (so that
// "width" or "image.width" suggest "render.width"). Ties go as NearestName's
// (util/edit_distance.h): to the longer common prefix, then the earlier table entry. Only the
// first 40 bytes of `name` are compared (also in nearestSectionName).
std::string nearestParameterName(std::string_view name);
// The section closest to `section`.
std::string nearestSectionName(std::string_view section);

// A Scene with every default of the table applied. Prefer it to Scene{}, whose fields are zero.
Scene defaultScene();

// Checks `value` against `parameter` and returns it in canonical form (an integer given for a
// Real becomes a double; a double with an exact integer value given for an Integer becomes an
// int64_t). Throws UserError(parameter.name(), ...) for a wrong type, a vector of the wrong
// length, NaN or infinity, a value out of range, or a word that is not one of the choices.
ParameterValue checkedValue(const Parameter& parameter, const ParameterValue& value);

// The message for a key or section of a light past the last one ("light8", "light9.kind"):
// nothing for any other name.
std::optional<std::string> pastTheLights(std::string_view name);

// Finds `name`, checks `value` and applies it. Throws UserError(name, ...): for an unknown
// name with the nearest valid one, "unknown key 'render.widht' (did you mean 'render.width'?)",
// and otherwise as checkedValue, e.g. "render.width = 0 is out of range [1, 16384]".
void setParameter(Scene& scene, std::string_view name, const ParameterValue& value);

// Checks every value against the table (for Scenes built in code) and then the conditions that
// involve more than one value or a whole vector; throws a UserError naming the key to change.
// Among them: fractal.c has as many components as fractal.algebra's dimension; slice.origin and
// slice.axes are only for the 8-component algebras, which take none of slice.normal,
// slice.distance, slice.left, slice.right and slice.angles but their defaults; slice.axes holds
// three independent directions. The rules, one function each and in the order checked, are
// sceneRules() (scene_rules.h); the first that the scene breaks is reported.
void validateScene(const Scene& scene);

// What the value must be, for messages: "an integer", "an array of 3 numbers", "an array of 4
// or 8 numbers", ...
std::string describeType(const Parameter& parameter);
// The allowed values, for help and comments: "[1, 16384]", "8 or 16", "\"sphere\" or ...".
std::string describeRange(const Parameter& parameter);

// A value in TOML syntax, exactly: reals always carry a '.' or exponent (or are nan / inf) and
// have the shortest digits that read back to the same double; strings are quoted and escaped.
std::string formatValue(const ParameterValue& value);
// formatValue, but a value of a parameter with groups is written as that many arrays
// ([[1.0, 0.0, ...], [...], [...]]), as scene files may write it.
std::string formatParameterValue(const Parameter& parameter, const ParameterValue& value);

// Every parameter with its type, default (in TOML syntax), allowed values and help, grouped by
// section: the text of `quaternia render --help`.
std::string parameterHelp();

// The same in Markdown, one table per section under a "## [section]" heading after a list of
// links to them: the body of docs/parameters.md (`quaternia reference parameters`), generated so
// that the page cannot fall behind the table.
std::string parameterReference();

}  // namespace quaternia
