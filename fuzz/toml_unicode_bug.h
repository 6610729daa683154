// Debian 12's toml++ 3.3.0 reaches TOML_UNREACHABLE (__builtin_unreachable, undefined behaviour)
// in is_non_ascii_horizontal_whitespace for some code points where it looks for whitespace
// (upstream issue marzer/tomlplusplus#295, fixed by pull request #305, after 3.3.0): U+00A1 to
// U+0499, U+2C5E to U+3057 but U+3000, and U+FB26 to U+FEFE (its blocks 0, 11 and 63 of 0x3FA
// code points from U+00A0, which its bit mask lets through and its switch lacks; the fuzzer found
// U+FC3F outside the ranges first written here). It is not Quaternia's to fix, and under UBSan
// every such input would end the run, so the scene targets leave those inputs out.
#pragma once

#include <string_view>

inline bool hitsTomlUnicodeBug(std::string_view text) {
    for (size_t i = 0; i < text.size(); ++i) {
        const auto byte = [&](size_t k) { return i + k < text.size() ? uint8_t(text[i + k]) : 0; };
        char32_t c = 0;
        if ((byte(0) & 0xE0) == 0xC0)
            c = char32_t(byte(0) & 0x1F) << 6 | (byte(1) & 0x3F);
        else if ((byte(0) & 0xF0) == 0xE0)
            c = char32_t(byte(0) & 0x0F) << 12 | char32_t(byte(1) & 0x3F) << 6 | (byte(2) & 0x3F);
        else
            continue;
        if ((c >= 0xA1 && c <= 0x499) || (c >= 0x2C5E && c <= 0x3057 && c != 0x3000) ||
            (c >= 0xFB26 && c <= 0xFEFE))
            return true;
    }
    return false;
}
