#include "quaternia/util/edit_distance.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace quaternia {
namespace {

// The whole dynamic-programming table of the Levenshtein distance (Wagner and Fischer, 1974).
size_t wholeTableDistance(std::string_view a, std::string_view b) {
    std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
    for (size_t i = 0; i <= a.size(); ++i)
        d[i][0] = i;
    for (size_t j = 0; j <= b.size(); ++j)
        d[0][j] = j;
    for (size_t i = 1; i <= a.size(); ++i)
        for (size_t j = 1; j <= b.size(); ++j)
            d[i][j] = std::min(
                {d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] != b[j - 1])});
    return d[a.size()][b.size()];
}

TEST(EditDistance, CountsSingleCharacterEdits) {
    EXPECT_EQ(editDistance("", ""), 0u);
    EXPECT_EQ(editDistance("", "abc"), 3u);
    EXPECT_EQ(editDistance("width", "width"), 0u);
    EXPECT_EQ(editDistance("widht", "width"), 2u);  // no transpositions
    EXPECT_EQ(editDistance("kitten", "sitting"), 3u);
    EXPECT_EQ(editDistance("sitting", "kitten"), 3u);
    // Above the bound, bound + 1; at or below it, exact.
    EXPECT_EQ(editDistance("kitten", "sitting", 3), 3u);
    EXPECT_EQ(editDistance("kitten", "sitting", 2), 3u);
    EXPECT_EQ(editDistance("kitten", "sitting", 0), 1u);
    EXPECT_EQ(editDistance("a", "abcdefgh", 4), 5u);
    EXPECT_EQ(editDistance("abcdefgh", "hgfedcba", 1), 2u);
}

TEST(EditDistance, AgreesWithTheWholeTable) {
    // Short texts over a small alphabet (many matches), words of both kinds' lengths (the
    // bit-parallel path holds up to 64 bytes, the row-by-row one the rest) and every bound.
    std::vector<std::string> texts = {"", "a", "ab", "ba", "abc", "cab", "aabbcc", "abcabc"};
    uint64_t state = 12345;
    auto next = [&state] { return state = state * 6364136223846793005u + 1442695040888963407u; };
    for (size_t length : {5, 17, 40, 63, 64, 65, 70, 130}) {
        for (int copy = 0; copy < 3; ++copy) {
            std::string text;
            for (size_t i = 0; i < length; ++i)
                text += char('a' + (next() >> 33) % 4);
            texts.push_back(text);
        }
    }
    for (const std::string& a : texts) {
        for (const std::string& b : texts) {
            const size_t whole = wholeTableDistance(a, b);
            ASSERT_EQ(editDistance(a, b), whole) << a << " / " << b;
            for (size_t bound : {size_t(0), size_t(1), whole / 2, whole, whole + 3})
                ASSERT_EQ(editDistance(a, b, bound), std::min(whole, bound + 1))
                    << a << " / " << b << " bound " << bound;
        }
    }
}

TEST(NearestName, ChoosesTheFewestEdits) {
    EXPECT_EQ(nearestName("rabit", {"dendrite", "rabbit", "basilica"}), "rabbit");
    EXPECT_EQ(nearestName("basilisk", {"rabbit", "dendrite", "basilica"}), "basilica");
    EXPECT_EQ(nearestName("rendr", {"fractal", "slice", "camera", "render"}), "render");
}

// "shade" is 3 edits from both "slice" and "shading"; the common prefix decides, and without
// one the earlier candidate.
TEST(NearestName, BreaksTiesByTheCommonPrefixThenTheOrder) {
    EXPECT_EQ(nearestName("shade", {"slice", "shading"}), "shading");
    EXPECT_EQ(nearestName("shade", {"shading", "slice"}), "shading");
    EXPECT_EQ(nearestName("ch", {"cubic", "chrome"}), "chrome");
    EXPECT_EQ(nearestName("xy", {"ab", "cd"}), "ab");
    EXPECT_EQ(nearestName("xy", {"cd", "ab"}), "cd");
    EXPECT_EQ(nearestName("ab", {"ax", "ay"}), "ax");
}

TEST(NearestName, IsEmptyWithoutCandidates) {
    EXPECT_EQ(nearestName("anything", {}), "");
    EXPECT_EQ(NearestName("anything").best(), "");
    EXPECT_EQ(nearestName("", {"a", "bb"}), "a");
}

// bound() is the best distance so far: what editDistance may stop at, since a farther candidate
// cannot win.
TEST(NearestName, BoundsTheDistancesByTheBestSoFar) {
    NearestName nearest("width");
    EXPECT_EQ(nearest.bound(), SIZE_MAX);
    nearest.consider("height");
    EXPECT_EQ(nearest.bound(), editDistance("width", "height"));
    EXPECT_EQ(nearest.best(), "height");
    nearest.consider("widths");
    EXPECT_EQ(nearest.bound(), 1u);
    nearest.consider("a much longer name than any other");  // pruned, and not chosen
    EXPECT_EQ(nearest.bound(), 1u);
    EXPECT_EQ(nearest.best(), "widths");
    nearest.consider("width");
    EXPECT_EQ(nearest.bound(), 0u);
    EXPECT_EQ(nearest.best(), "width");
}

// A distance the caller measured its own way counts as given.
TEST(NearestName, TakesTheCallersDistances) {
    NearestName nearest("x");
    nearest.consider("far", 7);
    nearest.consider("near", 2);
    nearest.consider("also near", 2);
    nearest.consider("farther", 9);
    EXPECT_EQ(nearest.best(), "near");
    EXPECT_EQ(nearest.bound(), 2u);
}

// With distances cut off at the best so far it must choose as with the whole distances.
TEST(NearestName, AgreesWithTheWholeDistances) {
    uint64_t state = 777;
    auto next = [&state] { return state = state * 6364136223846793005u + 1442695040888963407u; };
    auto word = [&] {
        std::string text;
        const size_t length = (next() >> 33) % 9;
        for (size_t i = 0; i < length; ++i)
            text += char('a' + (next() >> 33) % 3);
        return text;
    };
    for (int trial = 0; trial < 500; ++trial) {
        const std::string query = word();
        std::vector<std::string> candidates(1 + (next() >> 33) % 12);
        for (std::string& candidate : candidates)
            candidate = word();
        std::string expected;
        size_t bestDistance = SIZE_MAX, bestPrefix = 0;
        for (const std::string& candidate : candidates) {
            const size_t distance = wholeTableDistance(query, candidate);
            const size_t prefix =
                std::mismatch(query.begin(), query.end(), candidate.begin(), candidate.end())
                    .first -
                query.begin();
            if (distance < bestDistance || (distance == bestDistance && prefix > bestPrefix))
                expected = candidate, bestDistance = distance, bestPrefix = prefix;
        }
        ASSERT_EQ(nearestName(query, candidates), expected) << query;
    }
}

}  // namespace
}  // namespace quaternia
