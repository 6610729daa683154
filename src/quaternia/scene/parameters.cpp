// The table's machinery: access and lookup by name, the nearest name to an unknown one, the
// default scene and setParameter. The table itself is parameter_table*.cpp; the checks of a
// value parameter_checks.cpp, those of a whole scene scene_rules.cpp, and the text of values and
// help parameter_text.cpp and parameter_help.cpp.
#include "quaternia/scene/parameters.h"

#include <algorithm>
#include <string>

#include "quaternia/util/edit_distance.h"
#include "quaternia/util/error.h"

namespace quaternia {

// ---- Table access -----------------------------------------------------------------------------

const std::vector<Parameter>& parameterTable() {
    static const std::vector<Parameter> table = buildParameterTable();
    return table;
}

const std::vector<std::string>& parameterSections() {
    static const std::vector<std::string> sections = [] {
        std::vector<std::string> names;
        for (const auto& p : parameterTable())
            if (names.empty() || names.back() != p.section) names.push_back(p.section);
        return names;
    }();
    return sections;
}

const Parameter* findParameter(std::string_view name) {
    for (const auto& p : parameterTable())
        if (name.size() == p.section.size() + 1 + p.key.size() && name.starts_with(p.section) &&
            name[p.section.size()] == '.' && name.ends_with(p.key))
            return &p;
    return nullptr;
}

// ---- Nearest names ----------------------------------------------------------------------------

namespace {

// Names are compared by their first 40 bytes, more than the longest in the table has (23): no
// typo is longer, and the edit distance costs the product of the lengths (an explorer query or a
// scene file can hold unknown keys of thousands of bytes).
constexpr std::size_t kMaxComparedLength = 40;

}  // namespace

std::string nearestParameterName(std::string_view name) {
    name = name.substr(0, kMaxComparedLength);
    std::size_t dot = name.find('.');
    bool hasSection = dot != std::string_view::npos;
    std::string_view section = hasSection ? name.substr(0, dot) : std::string_view();
    std::string_view key = hasSection ? name.substr(dot + 1) : name;
    const auto& sections = parameterSections();
    bool knownSection = std::find(sections.begin(), sections.end(), section) != sections.end();
    NearestName nearest(name);
    for (const auto& p : parameterTable()) {
        // Keys are compared within their section first: a key of another section costs 2
        // edits more, and 1 more where the section is missing or unknown (so "width" and
        // "image.width" suggest "render.width"). The whole name catches typos in the section.
        // Levenshtein favours short keys, so a key that the typed one begins ("max_iter",
        // "light") counts as 1 edit away.
        // Distances above the best so far cannot win, so each is computed only up to it.
        const std::size_t best = nearest.bound();
        std::size_t sectionCost = section == p.section ? 0 : knownSection ? 2 : 1;
        std::size_t keyDistance = editDistance(key, p.key, best - std::min(best, sectionCost));
        if (key.size() >= 3 && p.key.starts_with(key))
            keyDistance = std::min<std::size_t>(keyDistance, 1);
        const std::string candidate = p.name();
        nearest.consider(candidate,
                         std::min(editDistance(name, candidate, best), keyDistance + sectionCost));
    }
    return nearest.best();
}

std::string nearestSectionName(std::string_view section) {
    section = section.substr(0, kMaxComparedLength);
    return nearestName(section, parameterSections());
}

// ---- Defaults and setting ---------------------------------------------------------------------

Scene defaultScene() {
    Scene scene;
    for (const auto& p : parameterTable())
        p.apply(scene, p.defaultValue);
    return scene;
}

std::optional<std::string> pastTheLights(std::string_view name) {
    // "lightN" or "lightN.key" with N a number past the last light section.
    if (name.substr(0, 5) != "light") return std::nullopt;
    std::string_view digits = name.substr(5);
    digits = digits.substr(0, digits.find('.'));
    if (digits.empty() || digits.size() > 6 ||
        digits.find_first_not_of("0123456789") != std::string_view::npos)
        return std::nullopt;
    if (std::stoi(std::string(digits)) <= kExtraLights) return std::nullopt;
    return "too many lights: [light" + std::string(digits) + "] is past the limit of " +
           std::to_string(kExtraLights) + " lights besides the key light ([light1] .. [light" +
           std::to_string(kExtraLights) + "])";
}

void setParameter(Scene& scene, std::string_view name, const ParameterValue& value) {
    const Parameter* p = findParameter(name);
    if (p == nullptr && pastTheLights(name))
        throw UserError(std::string(name), *pastTheLights(name));
    if (p == nullptr)
        throw UserError(std::string(name), "unknown key '" + std::string(name) +
                                               "' (did you mean '" + nearestParameterName(name) +
                                               "'?)");
    p->apply(scene, checkedValue(*p, value));
}

}  // namespace quaternia
