// Plain values in and out of the byte records of cells files (cell_grid.cpp, certified_set.cpp):
// native byte order (the files are read back by the machine kind that wrote them; the magic
// line names the format).
#pragma once

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace quaternia {

template <typename T>
void appendValue(std::vector<uint8_t>& out, T value) {
    const size_t at = out.size();
    out.resize(at + sizeof(T));
    std::memcpy(out.data() + at, &value, sizeof(T));
}

// Reads a T at `at` and advances it; throws std::runtime_error("truncated") past `end`.
template <typename T>
T takeValue(const uint8_t*& at, const uint8_t* end) {
    if (end - at < ptrdiff_t(sizeof(T))) throw std::runtime_error("truncated");
    T value;
    std::memcpy(&value, at, sizeof(T));
    at += sizeof(T);
    return value;
}

}  // namespace quaternia
