// Values as text: in TOML syntax for scene files and messages (formatValue), and the bounds of a
// range for people (interval), shared by the checks' messages and the help.
#include "quaternia/scene/parameter_text.h"

#include <cmath>
#include <cstdint>
#include <variant>
#include <vector>

#include "quaternia/scene/parameters.h"
#include "quaternia/util/number_format.h"

namespace quaternia {
namespace parameter_text {

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

// Appended piecewise: GCC 12 warns falsely (-Wrestrict, bug 105329) about "[" + std::string.
std::string interval(const Parameter& p) {
    std::string out = "[";
    out.append(plainNumber(p.minimum)).append(", ").append(plainNumber(p.maximum)) += "]";
    return out;
}

std::string markdownCell(const std::string& text) {
    std::string out;
    bool inCode = false;
    for (char ch : text) {
        if (ch == '`') inCode = !inCode;
        if (ch == '|') {
            out += "\\|";
        } else if (ch == '\n') {
            out += ' ';
        } else if (!inCode && (ch == '*' || ch == '\\')) {
            out += '\\';
            out += ch;
        } else if (!inCode && ch == '<') {
            out += "&lt;";
        } else {
            out += ch;
        }
    }
    return out;
}

std::string markdownCode(const std::string& text) {
    std::string out = "`";
    for (char ch : text)
        out += ch == '|' ? std::string("\\|") : std::string(1, ch);
    return out + "`";
}

}  // namespace parameter_text

std::string formatValue(const ParameterValue& value) {
    struct Formatter {
        std::string operator()(double x) const { return tomlReal(x); }
        std::string operator()(int64_t n) const { return std::to_string(n); }
        std::string operator()(bool b) const { return b ? "true" : "false"; }
        std::string operator()(const std::string& text) const {
            return parameter_text::quoted(text);
        }
        std::string operator()(const std::vector<double>& v) const {
            std::string out = "[";
            for (std::size_t i = 0; i < v.size(); ++i)
                out += (i ? ", " : "") + tomlReal(v[i]);
            return out + "]";
        }
    };
    return std::visit(Formatter{}, value);
}

std::string formatParameterValue(const Parameter& p, const ParameterValue& value) {
    const auto* v = std::get_if<std::vector<double>>(&value);
    if (p.groups == 0 || v == nullptr || v->empty() || v->size() % p.groups != 0)
        return formatValue(value);
    const std::size_t length = v->size() / p.groups;
    std::string out = "[";
    for (std::size_t start = 0; start < v->size(); start += length) {
        if (start > 0) out += ", ";
        out += formatValue(std::vector<double>(v->begin() + std::ptrdiff_t(start),
                                               v->begin() + std::ptrdiff_t(start + length)));
    }
    return out + "]";
}

}  // namespace quaternia
