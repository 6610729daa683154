#include "quaternia/util/number_format.h"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace quaternia {

std::string shortestNumber(double x) {
    std::array<char, 32> buffer{};
    auto [end, error] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), x);
    return error == std::errc{} ? std::string(buffer.data(), end) : std::string("nan");
}

std::string tomlReal(double x) {
    if (std::isnan(x)) return "nan";
    if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
    std::string text = shortestNumber(x);
    if (text.find_first_of(".e") == std::string::npos) text += ".0";
    return text;
}

std::string plainNumber(double x) {
    std::array<char, 64> buffer{};
    auto format = std::abs(x) >= 1e-6 && std::abs(x) < 1e15 ? std::chars_format::fixed
                                                            : std::chars_format::general;
    auto [end, error] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), x, format);
    return error == std::errc{} ? std::string(buffer.data(), end) : shortestNumber(x);
}

std::string roundedNumber(double x, int digits) {
    if (x == 0) x = 0;  // no "-0"
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, x);
    // Within `digits` digits of the largest double the rounded text lies beyond it and would not
    // read back (--c refuses it as out of range): all 17 digits there.
    if (std::isinf(std::strtod(buffer, nullptr)) && !std::isinf(x))
        std::snprintf(buffer, sizeof buffer, "%.17g", x);
    return buffer;
}

}  // namespace quaternia
