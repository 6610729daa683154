#include "quaternia/util/edit_distance.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>

namespace quaternia {
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

std::size_t commonPrefixLength(std::string_view a, std::string_view b) {
    std::size_t n = 0;
    while (n < a.size() && n < b.size() && a[n] == b[n])
        ++n;
    return n;
}

}  // namespace

std::size_t editDistance(std::string_view a, std::string_view b, std::size_t bound) {
    bound = std::min(bound, std::numeric_limits<std::size_t>::max() - 1);
    if (a.size() > b.size()) std::swap(a, b);
    // The lengths' difference is a lower bound: most candidates of a nearest-name search are far.
    if (b.size() - a.size() > bound) return bound + 1;
    if (a.empty()) return b.size();
    if (a.size() <= 64) return std::min(bitParallelDistance(a, b), bound + 1);
    return rowByRowDistance(a, b, bound);
}

void NearestName::consider(std::string_view candidate, std::size_t distance) {
    const std::size_t prefix = commonPrefixLength(query_, candidate);
    if (distance < bestDistance_ || (distance == bestDistance_ && prefix > bestPrefix_))
        best_ = candidate, bestDistance_ = distance, bestPrefix_ = prefix;
}

void NearestName::consider(std::string_view candidate) {
    consider(candidate, editDistance(query_, candidate, bound()));
}

std::string nearestName(std::string_view query, const std::vector<std::string>& candidates) {
    NearestName nearest(query);
    for (const std::string& candidate : candidates)
        nearest.consider(candidate);
    return nearest.best();
}

}  // namespace quaternia
