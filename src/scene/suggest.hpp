#pragma once
// "Did you mean" suggestions for mistyped names.
#include <string>
#include <vector>

namespace collide::scene {

// Candidates within a small edit distance of `word`, closest first (at most three).
std::vector<std::string> nearMatches(const std::string& word,
                                     const std::vector<std::string>& candidates);

// ", did you mean 'a' or 'b'?" or "" when nothing is close.
std::string didYouMean(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace collide::scene
