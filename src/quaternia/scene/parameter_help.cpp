// What a parameter takes, in words for people: its type and allowed values in messages and
// comments (describeType, describeRange), and the whole table as --help lists it and as
// docs/parameters.md shows it (parameterReference).
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "quaternia/scene/parameter_text.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/util/number_format.h"

namespace quaternia {
namespace {

using parameter_text::interval;
using parameter_text::markdownCell;
using parameter_text::markdownCode;
using parameter_text::quoted;
using parameter_text::vectorLength;

// "a", "a or b", "a, b or c".
std::string joinAlternatives(const std::vector<std::string>& items) {
    std::string out;
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (i > 0) out += i + 1 == items.size() ? " or " : ", ";
        out += items[i];
    }
    return out;
}

// "4 or 8": the allowed lengths of a Components parameter.
std::string lengthsText(const std::vector<std::size_t>& lengths) {
    std::vector<std::string> counts;
    for (std::size_t n : lengths)
        counts.push_back(std::to_string(n));
    return joinAlternatives(counts);
}

// The type as --help shows it after the default: "real", "3 reals", "4 or 8 reals".
std::string typeName(const Parameter& p) {
    switch (p.type) {
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
            return "2 reals";
        case ParameterType::Vector3:
            return "3 reals";
        case ParameterType::Vector4:
            return "4 reals";
        case ParameterType::Vector6:
            return "6 reals";
        case ParameterType::Components: {
            // "4 or 8 reals", "empty or 24 reals"
            std::vector<std::string> counts;
            for (std::size_t n : p.lengths)
                counts.push_back(n == 0 ? "empty" : std::to_string(n));
            return joinAlternatives(counts) + " reals";
        }
    }
    return "?";
}

// [light2] .. [light7] are built by [light1]'s function (parameter_table_scenery.cpp): the help
// and the reference name their keys once.
bool isRepeatedLight(const std::string& section) {
    return section.size() > 5 && section.compare(0, 5, "light") == 0 && section != "light1";
}

const std::string kRepeatedLights = "[light2] .. [light" + std::to_string(kExtraLights) + "]";

}  // namespace

std::string describeType(const Parameter& p) {
    switch (p.type) {
        case ParameterType::Real:
            return "a number";
        case ParameterType::Integer:
            return "an integer";
        case ParameterType::Boolean:
            return "true or false";
        case ParameterType::Text:
            return "a string";
        case ParameterType::Choice:
            return describeRange(p);
        case ParameterType::Vector2:
        case ParameterType::Vector3:
        case ParameterType::Vector4:
        case ParameterType::Vector6:
            return "an array of " + std::to_string(vectorLength(p.type)) + " numbers";
        case ParameterType::Components: {
            // "an array of 4 or 8 numbers", "an empty array or an array of 24 numbers (or 3
            // arrays of 8)".
            std::vector<std::size_t> counts;
            for (std::size_t n : p.lengths)
                if (n > 0) counts.push_back(n);
            std::string out = "an array of " + lengthsText(counts) + " numbers";
            if (p.groups > 0) {
                std::vector<std::size_t> lengths;
                for (std::size_t n : counts)
                    if (n % p.groups == 0) lengths.push_back(n / p.groups);
                if (!lengths.empty())
                    out += " (or " + std::to_string(p.groups) + " arrays of " +
                           lengthsText(lengths) + ")";
            }
            if (counts.size() < p.lengths.size()) out = "an empty array or " + out;
            return out;
        }
    }
    return "?";
}

std::string describeRange(const Parameter& p) {
    switch (p.type) {
        case ParameterType::Real:
            return interval(p);
        case ParameterType::Integer: {
            if (p.allowedIntegers.empty()) return interval(p);
            std::vector<std::string> values;
            for (int64_t n : p.allowedIntegers)
                values.push_back(std::to_string(n));
            return joinAlternatives(values);
        }
        case ParameterType::Boolean:
            return "true or false";
        case ParameterType::Text:
            return plainNumber(p.minimum) + " to " + plainNumber(p.maximum) + " characters";
        case ParameterType::Choice: {
            std::vector<std::string> words;
            for (const auto& choice : p.choices)
                words.push_back(quoted(choice));
            return joinAlternatives(words);
        }
        case ParameterType::Vector2:
        case ParameterType::Vector3:
        case ParameterType::Vector4:
        case ParameterType::Vector6:
        case ParameterType::Components:
            return "each in " + interval(p);
    }
    return "?";
}

std::string parameterHelp() {
    std::string out =
        "Scene parameters. Set them in a scene file as `key = value` under `[section]`, or on the\n"
        "command line as --set section.key=value, the value in TOML syntax (a bare word such as\n"
        "fixed-step or z^3+c is taken as a string).\n";
    std::string section;
    for (const auto& p : parameterTable()) {
        if (isRepeatedLight(p.section)) {
            if (p.section != section && p.section == "light2")
                out += "\n" + kRepeatedLights + "\n  The same keys as [light1], for more lights.\n";
            section = p.section;
            continue;
        }
        if (p.section != section) out += "\n[" + (section = p.section) + "]\n";
        out += "  " + p.name() + " = " + formatValue(p.defaultValue) + "    (" + typeName(p) +
               ", " + describeRange(p) + ")\n      " + p.help + "\n";
    }
    return out;
}

std::string parameterReference() {
    // The sections as headings, each linked from the list at the top: GitHub's anchor of
    // "[fractal]" is "fractal", of "[light2] .. [light7]" "light2--light7".
    std::vector<std::pair<std::string, std::string>> headings;  // link text, anchor
    for (const std::string& section : parameterSections()) {
        if (section == "light2")
            headings.emplace_back("light2 .. light" + std::to_string(kExtraLights),
                                  "light2--light" + std::to_string(kExtraLights));
        else if (!isRepeatedLight(section))
            headings.emplace_back(section, section);
    }
    std::string out =
        "Every key of a scene, by section. Set them in a scene file as `key = value` under\n"
        "`[section]`, or on the command line as `--set section.key=value`, the value in TOML "
        "syntax\n(a bare word such as `fixed-step` or `z^3+c` is taken as a string). The file, "
        "then `--preset`,\nthen each `--set` apply in that order; a value out of range is "
        "refused with the key named.\n\nSections:";
    for (std::size_t i = 0; i < headings.size(); ++i)
        out += std::string(i == 0 ? " " : ", ") + "[" + headings[i].first + "](#" +
               headings[i].second + ")";
    out += ".\n";
    const std::string tableHead =
        "| key | type | default | allowed | meaning |\n|---|---|---|---|---|\n";
    std::string section;
    for (const auto& p : parameterTable()) {
        if (isRepeatedLight(p.section)) {
            if (p.section != section && p.section == "light2")
                out += "\n## " + kRepeatedLights +
                       "\n\nThe keys of [light1](#light1), with the same defaults, for more "
                       "lights: `light2.enabled`, ... `light" +
                       std::to_string(kExtraLights) + ".angular_radius`.\n";
            section = p.section;
            continue;
        }
        if (p.section != section) out += "\n## [" + (section = p.section) + "]\n\n" + tableHead;
        out += "| " + markdownCode(p.name()) + " | " + markdownCell(typeName(p)) + " | " +
               markdownCode(formatParameterValue(p, p.defaultValue)) + " | " +
               markdownCell(describeRange(p)) + " | " + markdownCell(p.help) + " |\n";
    }
    return out;
}

}  // namespace quaternia
