#include "quaternia/scene/parameters.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include "quaternia/util/error.h"

namespace quaternia {

namespace {

// ---- Formatting -------------------------------------------------------------------------------

// Shortest digits that read back to the same double (std::to_chars), as TOML: a '.' or exponent
// is added where the digits alone would read as an integer.
std::string formatReal(double x) {
    if (std::isnan(x)) return "nan";
    if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
    std::array<char, 64> buffer{};
    auto [end, ec] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), x);
    std::string text(buffer.data(), end);
    if (text.find_first_of(".e") == std::string::npos) text += ".0";
    return text;
}

// A bound for people: "16384", "0.0001", "-10000" rather than TOML's "16384.0".
std::string formatBound(double x) {
    std::array<char, 64> buffer{};
    auto format = std::abs(x) >= 1e-6 && std::abs(x) < 1e15 ? std::chars_format::fixed
                                                            : std::chars_format::general;
    auto [end, ec] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), x, format);
    return std::string(buffer.data(), end);
}

std::string quoted(const std::string& text) {
    std::string out = "\"";
    for (unsigned char ch : text) {
        switch (ch) {
            case '"':
                out += "\\\"";
                break;
            case '\\':
                out += "\\\\";
                break;
            case '\b':
                out += "\\b";
                break;
            case '\t':
                out += "\\t";
                break;
            case '\n':
                out += "\\n";
                break;
            case '\f':
                out += "\\f";
                break;
            case '\r':
                out += "\\r";
                break;
            default:
                if (ch < 0x20 || ch == 0x7f) {
                    static const char* digits = "0123456789ABCDEF";
                    out += "\\u00";
                    out += digits[ch >> 4];
                    out += digits[ch & 15];
                } else {
                    out += char(ch);
                }
        }
    }
    return out + "\"";
}

// "a", "a or b", "a, b or c".
std::string joinAlternatives(const std::vector<std::string>& items) {
    std::string out;
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (i > 0) out += i + 1 == items.size() ? " or " : ", ";
        out += items[i];
    }
    return out;
}

std::size_t vectorLength(ParameterType type) {
    switch (type) {
        case ParameterType::Vector2:
            return 2;
        case ParameterType::Vector3:
            return 3;
        case ParameterType::Vector4:
            return 4;
        case ParameterType::Vector6:
            return 6;
        default:
            return 0;
    }
}

// "4 or 8": the allowed lengths of a Components parameter.
std::string lengthsText(const std::vector<std::size_t>& lengths) {
    std::vector<std::string> counts;
    for (std::size_t n : lengths)
        counts.push_back(std::to_string(n));
    return joinAlternatives(counts);
}

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

// ---- Checks -----------------------------------------------------------------------------------

[[noreturn]] void throwWrongType(const Parameter& p, const ParameterValue& value) {
    throw UserError(p.name(),
                    p.name() + " must be " + describeType(p) + ", got " + formatValue(value));
}

void checkFinite(const Parameter& p, bool finite, const ParameterValue& value) {
    if (!finite) throw UserError(p.name(), p.name() + " must be finite, got " + formatValue(value));
}

// "[minimum, maximum]". Appended piecewise: GCC 12 warns falsely (-Wrestrict, bug 105329) about
// "[" + std::string.
std::string interval(const Parameter& p) {
    std::string out = "[";
    out.append(formatBound(p.minimum)).append(", ").append(formatBound(p.maximum)) += "]";
    return out;
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
                                                       formatBound(p.minimum) + " characters");
    if (double(text->size()) > p.maximum)
        throw UserError(p.name(), p.name() + " has " + std::to_string(text->size()) +
                                      " characters; at most " + formatBound(p.maximum) +
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
        checkRange(p, p.name() + "[" + std::to_string(i) + "]", (*v)[i], formatReal((*v)[i]));
    return *v;
}

// The 8-component algebras are sliced by slice.origin and slice.axes alone: the quaternion
// slice's keys must keep their defaults, or a scene would say more than it draws.
void checkSliceDefaults(const Scene& scene, const std::string& algebra) {
    for (const char* name :
         {"slice.normal", "slice.distance", "slice.left", "slice.right", "slice.angles"}) {
        const Parameter& p = *findParameter(name);
        if (p.read(scene) != p.defaultValue)
            throw UserError(name, std::string(name) + " applies to the 4-component algebras; the " +
                                      algebra + " algebra takes slice.origin and slice.axes");
    }
}

// Gram-Schmidt in order: each axis less its projections on the ones before must keep at least
// 1e-9 of its own length.
void checkSliceAxes(const std::vector<double>& axes) {
    if (axes.empty()) return;
    constexpr std::size_t kDimension = 8;
    std::vector<std::vector<double>> units;
    for (std::size_t a = 0; a * kDimension < axes.size(); ++a) {
        std::vector<double> v(axes.begin() + std::ptrdiff_t(a * kDimension),
                              axes.begin() + std::ptrdiff_t((a + 1) * kDimension));
        auto length = [](const std::vector<double>& x) {
            double sum = 0;
            for (double component : x)
                sum += component * component;
            return std::sqrt(sum);
        };
        const double own = length(v);
        const std::string axis = "slice.axes: axis " + std::to_string(a + 1);
        if (own == 0)
            throw UserError("slice.axes",
                            axis + " is zero; three independent directions are needed");
        for (const auto& unit : units) {
            double along = 0;
            for (std::size_t k = 0; k < kDimension; ++k)
                along += v[k] * unit[k];
            for (std::size_t k = 0; k < kDimension; ++k)
                v[k] -= along * unit[k];
        }
        const double rest = length(v);
        if (rest < 1e-9 * own)
            throw UserError("slice.axes", axis +
                                              " lies in the span of the axes before it; three "
                                              "independent directions are needed");
        for (double& component : v)
            component /= rest;
        units.push_back(std::move(v));
    }
}

}  // namespace

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

namespace {

// The Levenshtein distance of a pattern of 1 to 64 bytes and any text by Myers' bit-parallel
// algorithm (Myers, "A fast bit-vector algorithm for approximate string matching based on
// dynamic programming", J. ACM 1999), in Hyyro's formulation for the global distance (Hyyro,
// "Explaining and extending the bit-parallel approximate string matching algorithm of Myers",
// 2001): a column of the dynamic-programming table is kept as its vertical differences, +1 bits
// in `plus` and -1 bits in `minus`, one bit per pattern byte, and advanced a text byte at a time.
std::size_t bitParallelDistance(std::string_view pattern, std::string_view text) {
    std::array<std::uint64_t, 256> matches{};
    for (std::size_t i = 0; i < pattern.size(); ++i)
        matches[static_cast<unsigned char>(pattern[i])] |= std::uint64_t(1) << i;
    const std::uint64_t lastRow = std::uint64_t(1) << (pattern.size() - 1);
    std::uint64_t plus = ~std::uint64_t(0), minus = 0;
    std::size_t distance = pattern.size();
    for (const char c : text) {
        const std::uint64_t equal = matches[static_cast<unsigned char>(c)];
        const std::uint64_t verticalChange = equal | minus;
        const std::uint64_t horizontalChange = (((equal & plus) + plus) ^ plus) | equal;
        std::uint64_t horizontalPlus = minus | ~(horizontalChange | plus);
        std::uint64_t horizontalMinus = plus & horizontalChange;
        if (horizontalPlus & lastRow)
            ++distance;
        else if (horizontalMinus & lastRow)
            --distance;
        // The top row of the global table grows by one per text byte: a +1 enters at the top.
        horizontalPlus = (horizontalPlus << 1) | 1;
        horizontalMinus <<= 1;
        plus = horizontalMinus | ~(verticalChange | horizontalPlus);
        minus = horizontalPlus & verticalChange;
    }
    return distance;
}

// The textbook dynamic programme, one row at a time, for two texts longer than a word; a row's
// least entry is a lower bound (Ukkonen, "Algorithms for approximate string matching", 1985), so
// a distance above `bound` is known early.
std::size_t rowByRowDistance(std::string_view a, std::string_view b, std::size_t bound) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j)
        row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        std::size_t least = row[0];
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t above = row[j];
            const std::size_t edit = std::min(above, row[j - 1]) + 1;
            row[j] = std::min(edit, diagonal + (a[i - 1] != b[j - 1]));
            least = std::min(least, row[j]);
            diagonal = above;
        }
        if (least > bound) return bound + 1;
    }
    return row[b.size()];
}

}  // namespace

std::size_t editDistance(std::string_view a, std::string_view b, std::size_t bound) {
    bound = std::min(bound, std::numeric_limits<std::size_t>::max() - 1);
    if (a.size() > b.size()) std::swap(a, b);
    // The lengths' difference is a lower bound: most candidates of nearestParameterName are far.
    if (b.size() - a.size() > bound) return bound + 1;
    if (a.empty()) return b.size();
    if (a.size() <= 64) return std::min(bitParallelDistance(a, b), bound + 1);
    return rowByRowDistance(a, b, bound);
}

namespace {

// Names are compared by their first 40 bytes, more than the longest in the table has (23): no
// typo is longer, and the edit distance costs the product of the lengths (an explorer query or a
// scene file can hold unknown keys of thousands of bytes).
constexpr std::size_t kMaxComparedLength = 40;

std::size_t commonPrefixLength(std::string_view a, std::string_view b) {
    std::size_t n = 0;
    while (n < a.size() && n < b.size() && a[n] == b[n])
        ++n;
    return n;
}

// Fewer edits first; among equals, the longer common prefix ("shade" is nearer "shading" than
// "slice"), then the earlier candidate.
struct Nearest {
    std::string_view query;
    std::string best;
    std::size_t bestDistance = std::numeric_limits<std::size_t>::max();
    std::size_t bestPrefix = 0;

    void consider(const std::string& candidate, std::size_t distance) {
        std::size_t prefix = commonPrefixLength(query, candidate);
        if (distance < bestDistance || (distance == bestDistance && prefix > bestPrefix))
            best = candidate, bestDistance = distance, bestPrefix = prefix;
    }
};

}  // namespace

std::string nearestParameterName(std::string_view name) {
    name = name.substr(0, kMaxComparedLength);
    std::size_t dot = name.find('.');
    bool hasSection = dot != std::string_view::npos;
    std::string_view section = hasSection ? name.substr(0, dot) : std::string_view();
    std::string_view key = hasSection ? name.substr(dot + 1) : name;
    const auto& sections = parameterSections();
    bool knownSection = std::find(sections.begin(), sections.end(), section) != sections.end();
    Nearest nearest{name, {}};
    for (const auto& p : parameterTable()) {
        // Keys are compared within their section first: a key of another section costs 2
        // edits more, and 1 more where the section is missing or unknown (so "width" and
        // "image.width" suggest "render.width"). The whole name catches typos in the section.
        // Levenshtein favours short keys, so a key that the typed one begins ("max_iter",
        // "light") counts as 1 edit away.
        // Distances above the best so far cannot win, so each is computed only up to it.
        const std::size_t best = nearest.bestDistance;
        std::size_t sectionCost = section == p.section ? 0 : knownSection ? 2 : 1;
        std::size_t keyDistance = editDistance(key, p.key, best - std::min(best, sectionCost));
        if (key.size() >= 3 && p.key.starts_with(key))
            keyDistance = std::min<std::size_t>(keyDistance, 1);
        const std::string candidate = p.name();
        nearest.consider(candidate,
                         std::min(editDistance(name, candidate, best), keyDistance + sectionCost));
    }
    return nearest.best;
}

std::string nearestSectionName(std::string_view section) {
    section = section.substr(0, kMaxComparedLength);
    Nearest nearest{section, {}};
    for (const auto& candidate : parameterSections())
        nearest.consider(candidate, editDistance(section, candidate, nearest.bestDistance));
    return nearest.best;
}

Scene defaultScene() {
    Scene scene;
    for (const auto& p : parameterTable())
        p.apply(scene, p.defaultValue);
    return scene;
}

// ---- Checking and setting ---------------------------------------------------------------------

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

void validateScene(const Scene& scene) {
    for (const auto& p : parameterTable())
        checkedValue(p, p.read(scene));

    const CameraSettings& camera = scene.camera;
    Vector3d view = camera.lookAt - camera.position;
    if (dot(view, view) == 0)
        throw UserError("camera.look_at",
                        "camera.look_at equals camera.position; the camera needs a direction to "
                        "look in");
    // sin(angle between up and view) below 1e-9: no sideways axis can be built from them.
    if (length(cross(camera.up, view)) <= 1e-9 * length(camera.up) * length(view))
        throw UserError("camera.up", "camera.up = " +
                                         formatValue(std::vector<double>{camera.up.x, camera.up.y,
                                                                         camera.up.z}) +
                                         " is zero or parallel to the view direction "
                                         "camera.look_at - camera.position");

    const FractalSettings& fractal = scene.fractal;
    const int dimension = algebraDimension(fractal.algebra);
    const std::string algebra(algebraName(fractal.algebra));
    if (fractal.cComponents != dimension)
        throw UserError("fractal.c", "fractal.c has " + std::to_string(fractal.cComponents) +
                                         " components; the " + algebra + " algebra needs " +
                                         std::to_string(dimension));

    const SliceSettings& slice = scene.slice;
    if (dimension == 8) {
        checkSliceDefaults(scene, algebra);
        checkSliceAxes(slice.axes);
    } else {
        for (const auto& [key, values] :
             {std::pair<const char*, const std::vector<double>*>{"slice.origin", &slice.origin},
              {"slice.axes", &slice.axes}})
            if (!values->empty())
                throw UserError(key, std::string(key) +
                                         " is for the 8-component algebras (biquaternion, "
                                         "octonion); " +
                                         algebra +
                                         " slices are set by slice.normal, slice.distance, "
                                         "slice.left, slice.right and slice.angles");
        double normalLength = norm(slice.normal);
        if (normalLength == 0) throw UserError("slice.normal", "slice.normal must not be zero");
        // The 3D step of a marcher is the 4D distance times |s^_w| (docs/methods.md, Slices and
        // the step factor), so a w component that is merely tiny would stall every ray; 1e-6 of
        // the normal's length is the floor.
        if (std::abs(slice.normal[3]) < 1e-6 * normalLength)
            throw UserError("slice.normal",
                            "slice.normal needs a w component (the 4th): POV-Ray's slice computes "
                            "w = (distance - s.xyz) / s_w for each 3D point, so |s_w| must be at "
                            "least 1e-6 of the normal's length");
    }
    if (normSquared(slice.left) == 0)
        throw UserError("slice.left", "slice.left must not be zero (it is made unit length)");
    if (normSquared(slice.right) == 0)
        throw UserError("slice.right", "slice.right must not be zero (it is made unit length)");

    const ShadingSettings& shading = scene.shading;
    if (dot(shading.lightDirection, shading.lightDirection) == 0)
        throw UserError("shading.light_direction", "shading.light_direction must not be zero");
    if (shading.lightKind == LightKind::Spot &&
        dot(shading.spotTarget - shading.lightPosition,
            shading.spotTarget - shading.lightPosition) == 0)
        throw UserError("shading.spot_target",
                        "shading.spot_target must differ from shading.light_position");
    if (dot(shading.fillDirection, shading.fillDirection) == 0)
        throw UserError("shading.fill_direction", "shading.fill_direction must not be zero");

    const RenderSettings& render = scene.render;
    constexpr int64_t kMaximumSamples = int64_t{16384} * 16384 * 16;
    int64_t total = int64_t{render.width} * render.height * render.samples;
    if (total > kMaximumSamples)
        throw UserError("render.samples",
                        "render.width * render.height * render.samples = " +
                            std::to_string(render.width) + " * " + std::to_string(render.height) +
                            " * " + std::to_string(render.samples) + " = " + std::to_string(total) +
                            " samples, more than the limit of " + std::to_string(kMaximumSamples) +
                            " (16384 * 16384 * 16); lower render.samples or the image size");
}

// ---- Descriptions -----------------------------------------------------------------------------

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
            if (p.groupLength > 0 && counts.size() == 1 && counts[0] % p.groupLength == 0 &&
                counts[0] > p.groupLength)
                out += " (or " + std::to_string(counts[0] / p.groupLength) + " arrays of " +
                       std::to_string(p.groupLength) + ")";
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
            return formatBound(p.minimum) + " to " + formatBound(p.maximum) + " characters";
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

std::string formatValue(const ParameterValue& value) {
    struct Formatter {
        std::string operator()(double x) const { return formatReal(x); }
        std::string operator()(int64_t n) const { return std::to_string(n); }
        std::string operator()(bool b) const { return b ? "true" : "false"; }
        std::string operator()(const std::string& text) const { return quoted(text); }
        std::string operator()(const std::vector<double>& v) const {
            std::string out = "[";
            for (std::size_t i = 0; i < v.size(); ++i)
                out += (i ? ", " : "") + formatReal(v[i]);
            return out + "]";
        }
    };
    return std::visit(Formatter{}, value);
}

std::string formatParameterValue(const Parameter& p, const ParameterValue& value) {
    const auto* v = std::get_if<std::vector<double>>(&value);
    if (p.groupLength == 0 || v == nullptr || v->empty() || v->size() % p.groupLength != 0)
        return formatValue(value);
    std::string out = "[";
    for (std::size_t start = 0; start < v->size(); start += p.groupLength) {
        if (start > 0) out += ", ";
        out += formatValue(std::vector<double>(v->begin() + std::ptrdiff_t(start),
                                               v->begin() + std::ptrdiff_t(start + p.groupLength)));
    }
    return out + "]";
}

std::string parameterHelp() {
    std::string out =
        "Scene parameters. Set them in a scene file as `key = value` under `[section]`, or on the\n"
        "command line as --set section.key=value, the value in TOML syntax (a bare word such as\n"
        "fixed-step or z^3+c is taken as a string).\n";
    std::string section;
    for (const auto& p : parameterTable()) {
        // [light2] .. [light7] are [light1] again: named once.
        if (p.section.size() > 5 && p.section.substr(0, 5) == "light" && p.section != "light1") {
            if (p.section != section && p.section == "light2")
                out += "\n[light2] .. [light" + std::to_string(kExtraLights) +
                       "]\n  The same keys as [light1], for more lights.\n";
            section = p.section;
            continue;
        }
        if (p.section != section) out += "\n[" + (section = p.section) + "]\n";
        out += "  " + p.name() + " = " + formatValue(p.defaultValue) + "    (" + typeName(p) +
               ", " + describeRange(p) + ")\n      " + p.help + "\n";
    }
    return out;
}

}  // namespace quaternia
