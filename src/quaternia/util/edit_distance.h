// The edit distance between names, and the nearest of a list of names to one that is not in it:
// what every "unknown ... (did you mean ...?)" message suggests (scene keys and sections,
// presets). One rule for all of them, so that a typo is answered alike wherever it is made.
#pragma once

#include <cstddef>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace quaternia {

// Levenshtein distance (insertions, deletions and substitutions of single bytes); a distance
// above `bound` is reported as bound + 1 (and found sooner).
std::size_t editDistance(std::string_view a, std::string_view b,
                         std::size_t bound = std::numeric_limits<std::size_t>::max());

// The nearest of the candidates offered to it one at a time: fewer edits first; among equals,
// the longer common prefix with the query ("shade" is nearer "shading" than "slice"), then the
// earlier candidate. The caller measures the distances, so that it may count edits its own way
// (nearestParameterName weighs a key's section apart).
class NearestName {
  public:
    explicit NearestName(std::string_view query) : query_(query) {}

    // The distance of the best candidate so far (the largest std::size_t before the first). A
    // distance above it cannot win, so it is the bound to give editDistance.
    std::size_t bound() const { return bestDistance_; }

    // Offers `candidate` at `distance` edits from the query.
    void consider(std::string_view candidate, std::size_t distance);
    // Offers `candidate` at its edit distance from the query, computed only up to bound().
    void consider(std::string_view candidate);

    // The nearest candidate offered; empty if none was.
    const std::string& best() const { return best_; }

  private:
    std::string_view query_;
    std::string best_;
    std::size_t bestDistance_ = std::numeric_limits<std::size_t>::max();
    std::size_t bestPrefix_ = 0;
};

// The candidate nearest `query` by NearestName's order (edits, then common prefix, then the
// earlier candidate); empty if there are no candidates.
std::string nearestName(std::string_view query, const std::vector<std::string>& candidates);

}  // namespace quaternia
