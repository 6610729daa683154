// setParameter's checks of one value against its table entry: type, length, finiteness, range,
// choices and text that scene files can hold. Each refusal names the key and what it takes.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "quaternia/scene/parameter_text.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/util/error.h"
#include "quaternia/util/number_format.h"

namespace quaternia {
namespace {

using parameter_text::interval;
using parameter_text::vectorLength;

[[noreturn]] void throwWrongType(const Parameter& p, const ParameterValue& value) {
    throw UserError(p.name(),
                    p.name() + " must be " + describeType(p) + ", got " + formatValue(value));
}

void checkFinite(const Parameter& p, bool finite, const ParameterValue& value) {
    if (!finite) throw UserError(p.name(), p.name() + " must be finite, got " + formatValue(value));
}

// `label` is the name, or the name with a component index.
void checkRange(const Parameter& p, const std::string& label, double x, const std::string& shown) {
    if (x < p.minimum || x > p.maximum)
        throw UserError(p.name(), label + " = " + shown + " is out of range " + interval(p));
}

double checkedReal(const Parameter& p, const ParameterValue& value) {
    double x = 0;
    if (const auto* real = std::get_if<double>(&value))
        x = *real;
    else if (const auto* integer = std::get_if<int64_t>(&value))
        x = double(*integer);
    else
        throwWrongType(p, value);
    checkFinite(p, std::isfinite(x), value);
    checkRange(p, p.name(), x, formatValue(value));
    return x;
}

int64_t checkedInteger(const Parameter& p, const ParameterValue& value) {
    double x = 0;  // exact for every value in range, so the range check is exact too
    if (const auto* integer = std::get_if<int64_t>(&value)) {
        x = double(*integer);
    } else if (const auto* real = std::get_if<double>(&value)) {
        checkFinite(p, std::isfinite(*real), value);
        if (*real != std::trunc(*real)) throwWrongType(p, value);
        x = *real;
    } else {
        throwWrongType(p, value);
    }
    checkRange(p, p.name(), x, formatValue(value));
    auto n = int64_t(x);
    const auto& allowed = p.allowedIntegers;
    if (!allowed.empty() && std::find(allowed.begin(), allowed.end(), n) == allowed.end())
        throw UserError(p.name(), p.name() + " = " + formatValue(value) + " is not allowed; use " +
                                      describeRange(p));
    return n;
}

// The length of the well-formed UTF-8 sequence at text[i] (Unicode's table 3-7: no overlong
// forms, no surrogates, nothing above U+10FFFF), or 0.
std::size_t utf8Length(std::string_view text, std::size_t i) {
    const auto byte = [&](std::size_t k) {
        return i + k < text.size() ? static_cast<unsigned char>(text[i + k]) : 0u;
    };
    const unsigned lead = byte(0);
    const auto continuation = [&](std::size_t k, unsigned low = 0x80, unsigned high = 0xBF) {
        return byte(k) >= low && byte(k) <= high;
    };
    if (lead < 0x80) return 1;
    if (lead >= 0xC2 && lead <= 0xDF) return continuation(1) ? 2 : 0;
    if (lead >= 0xE0 && lead <= 0xEF) {
        const unsigned low = lead == 0xE0 ? 0xA0 : 0x80, high = lead == 0xED ? 0x9F : 0xBF;
        return continuation(1, low, high) && continuation(2) ? 3 : 0;
    }
    if (lead >= 0xF0 && lead <= 0xF4) {
        const unsigned low = lead == 0xF0 ? 0x90 : 0x80, high = lead == 0xF4 ? 0x8F : 0xBF;
        return continuation(1, low, high) && continuation(2) && continuation(3) ? 4 : 0;
    }
    return 0;
}

// Text values go into scene files, which are TOML: its strings must be UTF-8, and control
// characters other than tab (which a formula may hold as space) have no use in a formula or a
// name. Refusing both here keeps every accepted scene writable and readable again. The message
// leaves the bytes out.
void checkCharacters(const Parameter& p, std::string_view text) {
    for (std::size_t i = 0; i < text.size();) {
        const std::size_t length = utf8Length(text, i);
        if (length == 0)
            throw UserError(p.name(),
                            p.name() + " is not valid UTF-8 (byte " + std::to_string(i + 1) + ")");
        const auto c = static_cast<unsigned char>(text[i]);
        if ((c < 0x20 && c != '\t') || c == 0x7F)
            throw UserError(p.name(), p.name() + " contains a control character (byte " +
                                          std::to_string(i + 1) + ")");
        i += length;
    }
}

std::string checkedText(const Parameter& p, const ParameterValue& value) {
    const auto* text = std::get_if<std::string>(&value);
    if (text == nullptr) throwWrongType(p, value);
    if (p.type == ParameterType::Choice) {
        if (std::find(p.choices.begin(), p.choices.end(), *text) == p.choices.end())
            throwWrongType(p, value);
        return *text;
    }
    if (double(text->size()) < p.minimum)
        throw UserError(p.name(), p.minimum <= 1 ? p.name() + " must not be empty"
                                                 : p.name() + " must have at least " +
                                                       plainNumber(p.minimum) + " characters");
    if (double(text->size()) > p.maximum)
        throw UserError(p.name(), p.name() + " has " + std::to_string(text->size()) +
                                      " characters; at most " + plainNumber(p.maximum) +
                                      " are allowed");
    checkCharacters(p, *text);
    return *text;
}

std::vector<double> checkedVector(const Parameter& p, const ParameterValue& value) {
    const auto* v = std::get_if<std::vector<double>>(&value);
    if (v == nullptr) throwWrongType(p, value);
    bool allowedLength =
        p.type == ParameterType::Components
            ? std::find(p.lengths.begin(), p.lengths.end(), v->size()) != p.lengths.end()
            : v->size() == vectorLength(p.type);
    if (!allowedLength) throwWrongType(p, value);
    checkFinite(p, std::all_of(v->begin(), v->end(), [](double x) { return std::isfinite(x); }),
                value);
    for (std::size_t i = 0; i < v->size(); ++i)
        checkRange(p, p.name() + "[" + std::to_string(i) + "]", (*v)[i], tomlReal((*v)[i]));
    return *v;
}

}  // namespace

ParameterValue checkedValue(const Parameter& p, const ParameterValue& value) {
    switch (p.type) {
        case ParameterType::Real:
            return checkedReal(p, value);
        case ParameterType::Integer:
            return checkedInteger(p, value);
        case ParameterType::Boolean:
            if (!std::holds_alternative<bool>(value)) throwWrongType(p, value);
            return value;
        case ParameterType::Text:
        case ParameterType::Choice:
            return checkedText(p, value);
        case ParameterType::Vector2:
        case ParameterType::Vector3:
        case ParameterType::Vector4:
        case ParameterType::Vector6:
        case ParameterType::Components:
            return checkedVector(p, value);
    }
    throwWrongType(p, value);
}

}  // namespace quaternia
