#include "server/explore_request.h"

#include <set>
#include <string_view>
#include <variant>

#include "quaternia/fractal/fractal.h"
#include "quaternia/scene/json.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/presets.h"
#include "quaternia/scene/scene_file.h"
#include "quaternia/scene/scene_fractal.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

void checkAtMost(const std::string& key, int64_t value, int64_t limit, const std::string& what) {
    if (value > limit) {
        throw UserError(key, key + " = " + std::to_string(value) + " is above the explorer's " +
                                 "limit of " + std::to_string(limit) + " " + what);
    }
}

const char* typeName(ParameterType type) {
    switch (type) {
        case ParameterType::Real:
            return "real";
        case ParameterType::Integer:
            return "integer";
        case ParameterType::Boolean:
            return "boolean";
        case ParameterType::Text:
            return "text";
        case ParameterType::Choice:
            return "choice";
        case ParameterType::Vector2:
            return "vector2";
        case ParameterType::Vector3:
            return "vector3";
        case ParameterType::Vector4:
            return "vector4";
        case ParameterType::Vector6:
            return "vector6";
        case ParameterType::Components:
            return "components";
    }
    return "?";
}

// Single quotes for a POSIX shell: nothing inside is special except the quote itself.
std::string shellQuote(const std::string& text) {
    std::string out = "'";
    for (char ch : text) {
        if (ch == '\'')
            out += "'\\''";
        else
            out += ch;
    }
    out += '\'';
    return out;
}

}  // namespace

Scene sceneFromQuery(const Scene& base, const QueryParameters& query, const ExploreLimits& limits) {
    if (query.size() > limits.maxParameters) {
        throw UserError("query", "too many query parameters (" + std::to_string(query.size()) +
                                     "; at most " + std::to_string(limits.maxParameters) + ")");
    }
    // Which of two values would win is not the client's to guess: a repeated key is refused.
    std::set<std::string_view> names;
    for (const auto& entry : query)
        if (!names.insert(entry.first).second)
            throw UserError(entry.first, entry.first + " is given more than once");
    Scene scene = base;
    for (const auto& [name, value] : query) {
        if (name == kClientParameter || name == kCertifyParameter) continue;
        if (name.find('=') != std::string::npos || name.empty())
            throw UserError(name, "unknown key '" + name + "'");
        applyOverride(scene, name + "=" + value);
    }
    if (scene.animation.keys.size() > limits.maxAnimationKeys) {
        throw UserError("animation.keys",
                        "too many animation keys (" + std::to_string(scene.animation.keys.size()) +
                            "; at most " + std::to_string(limits.maxAnimationKeys) + ")");
    }
    checkSceneCost(scene, limits);
    return scene;
}

void checkSceneCost(const Scene& scene, const ExploreLimits& limits) {
    validateScene(scene);
    // The explorer's own bounds on cost, then the formula (a parse error names fractal.formula).
    checkAtMost("fractal.max_iterations", scene.fractal.maxIterations, limits.maxIterations,
                "iterations");
    checkAtMost("render.max_steps", scene.render.maxSteps, limits.maxSteps, "steps");
    fractalFromScene(scene);
}

void checkInteractiveImage(const Scene& scene, const ExploreLimits& limits) {
    int64_t pixels = int64_t{scene.render.width} * scene.render.height;
    checkAtMost("render.width", pixels, limits.interactivePixels, "pixels (width x height)");
    checkAtMost("render.samples", scene.render.samples, limits.interactiveSamples,
                "samples per pixel");
}

void checkDownloadImage(const Scene& scene, const ExploreLimits& limits) {
    checkAtMost("render.width", scene.render.width, limits.downloadSide, "pixels");
    checkAtMost("render.height", scene.render.height, limits.downloadSide, "pixels");
    int64_t rays = int64_t{scene.render.width} * scene.render.height * scene.render.samples;
    checkAtMost("render.samples", rays, limits.downloadRays, "rays (width x height x samples)");
}

void checkMeshRequest(const Scene& scene, const ExploreLimits& limits) {
    checkAtMost("mesh.resolution", scene.mesh.resolution, limits.meshResolution, "cells");
}

std::string clientIdFromQuery(const QueryParameters& query) {
    std::string id;
    for (const auto& [name, value] : query)
        if (name == kClientParameter) id = value;
    bool valid = id.size() <= 64;
    for (char ch : id) {
        bool word = (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') ||
                    (ch >= '0' && ch <= '9') || ch == '-' || ch == '_';
        valid = valid && word;
    }
    if (!valid) {
        throw UserError(kClientParameter, "client must be at most 64 letters, digits, '-' or '_'");
    }
    return id;
}

bool certifyFromQuery(const QueryParameters& query) {
    for (const auto& [name, value] : query) {
        if (name != kCertifyParameter) continue;
        if (value == "true" || value == "1") return true;
        if (value == "false" || value == "0") return false;
        throw UserError(kCertifyParameter, "certify must be true or false");
    }
    return false;
}

std::string renderCommandForScene(const Scene& scene) {
    const Scene defaults = defaultScene();
    std::string command = "quaternia render";
    for (const Parameter& p : parameterTable()) {
        ParameterValue value = p.read(scene);
        if (value == p.read(defaults) || p.section == "animation") continue;
        command += " --set " + shellQuote(p.name() + "=" + formatValue(value));
    }
    command += " -o quaternia.png";
    return command;
}

namespace {

// A ParameterValue (a number, boolean, string or array of numbers) as its JSON value.
Json jsonValue(const ParameterValue& v) {
    return std::visit([](const auto& x) { return Json(x); }, v);
}

}  // namespace

std::string parameterTableJson(const Scene& base) {
    Json table = Json::array();
    for (const Parameter& p : parameterTable()) {
        Json entry;
        entry["name"] = p.name();
        entry["section"] = p.section;
        entry["key"] = p.key;
        entry["type"] = typeName(p.type);
        entry["default"] = jsonValue(p.defaultValue);
        entry["value"] = jsonValue(p.read(base));
        entry["minimum"] = p.minimum;
        entry["maximum"] = p.maximum;
        entry["choices"] = p.choices;
        entry["allowed"] = p.allowedIntegers;
        // Components: the allowed lengths, and how many arrays of equal length a value may be
        // written as (0: one).
        entry["lengths"] = p.lengths;
        entry["groups"] = p.groups;
        entry["help"] = p.help;
        table.push_back(std::move(entry));
    }
    return jsonText(table) + "\n";
}

std::string presetsJson() {
    Json presets = Json::array();
    for (const Preset& preset : scenePresets()) {
        Json entry;
        entry["name"] = preset.name;
        entry["description"] = preset.description;
        entry["values"] = Json::object();
        for (const auto& [key, value] : preset.values)
            entry["values"][key] = jsonValue(checkedValue(*findParameter(key), value));
        presets.push_back(std::move(entry));
    }
    return jsonText(presets) + "\n";
}

std::string errorJson(const std::string& key, const std::string& message) {
    Json json;
    json["error"] = message;
    json["key"] = key;
    return jsonText(json) + "\n";
}

}  // namespace quaternia
