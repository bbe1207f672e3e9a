#include "scene/suggest.hpp"

#include <algorithm>
#include <cctype>

namespace collide::scene {
namespace {

// Levenshtein distance, case-insensitive.
std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> previous(b.size() + 1), current(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) previous[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                        std::tolower(static_cast<unsigned char>(b[j - 1]));
      current[j] =
          std::min({previous[j] + 1, current[j - 1] + 1, previous[j - 1] + (same ? 0 : 1)});
    }
    std::swap(previous, current);
  }
  return previous[b.size()];
}

}  // namespace

std::vector<std::string> nearMatches(const std::string& word,
                                     const std::vector<std::string>& candidates) {
  std::vector<std::pair<std::size_t, std::string>> scored;
  // Allow roughly one typo per three letters, and any candidate that starts with the word.
  const std::size_t limit = std::max<std::size_t>(2, word.size() / 3);
  for (const std::string& candidate : candidates) {
    const std::size_t distance = editDistance(word, candidate);
    const bool prefix = !word.empty() && candidate.rfind(word, 0) == 0;
    if (distance <= limit || prefix) scored.emplace_back(prefix ? 0 : distance, candidate);
  }
  std::stable_sort(scored.begin(), scored.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<std::string> result;
  for (std::size_t i = 0; i < scored.size() && i < 3; ++i) result.push_back(scored[i].second);
  return result;
}

std::string didYouMean(const std::string& word, const std::vector<std::string>& candidates) {
  const std::vector<std::string> matches = nearMatches(word, candidates);
  if (matches.empty()) return "";
  std::string text = "; did you mean ";
  for (std::size_t i = 0; i < matches.size(); ++i) {
    if (i > 0) text += (i + 1 == matches.size()) ? " or " : ", ";
    text += "'" + matches[i] + "'";
  }
  return text + "?";
}

}  // namespace collide::scene
