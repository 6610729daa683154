// Hand-written JSON output of the commands: string escaping and numbers that read back exactly.
#pragma once

#include <cmath>
#include <complex>
#include <cstdio>
#include <initializer_list>
#include <string>

#include "quaternia/algebra/quaternion.h"

namespace quaternia {

inline std::string jsonString(const std::string& s) {
    std::string out = "\"";
    for (char ch : s) {
        if (ch == '"' || ch == '\\') {
            out += '\\';
            out += ch;
        } else if (static_cast<unsigned char>(ch) < 0x20) {
            char buffer[8];
            std::snprintf(buffer, sizeof buffer, "\\u%04x", ch);
            out += buffer;
        } else {
            out += ch;
        }
    }
    out += '"';  // appended in place: `out + "\""` trips GCC 12's -Wrestrict false positive
    return out;
}

// 17 significant digits (round-trips a double); null for NaN and infinities, which JSON lacks.
inline std::string jsonNumber(double value) {
    if (!std::isfinite(value)) return "null";
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17g", value);
    return buffer;
}

// Built by appending: `"[" + std::string` trips GCC 12's -Wrestrict false positive.
inline std::string jsonArray(std::initializer_list<double> values) {
    std::string out = "[";
    for (double v : values) {
        if (out.size() > 1) out += ", ";
        out += jsonNumber(v);
    }
    out += ']';
    return out;
}

inline std::string jsonComplex(std::complex<double> z) {
    return jsonArray({z.real(), z.imag()});
}

inline std::string jsonQuaternion(const Quaternion& q) {
    return jsonArray({q.w, q.x, q.y, q.z});
}

}  // namespace quaternia
