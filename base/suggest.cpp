#include "base/suggest.hpp"

#include <algorithm>
#include <cctype>
#include <vector>

namespace clinch {
namespace {

std::string fold(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    if (c == ' ' || c == '\t') continue;
    out.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
  }
  return out;
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

template <typename Range>
std::optional<std::string> closest(std::string_view name, const Range& candidates) {
  const std::string folded = fold(name);
  std::optional<std::string> best;
  std::size_t best_distance = 0;
  for (const auto& candidate : candidates) {
    const std::string folded_candidate = fold(candidate);
    const std::size_t limit = std::max<std::size_t>(2, folded_candidate.size() / 3);
    const std::size_t distance = edit_distance(folded, folded_candidate);
    if (distance > limit) continue;
    if (!best || distance < best_distance) {
      best = std::string(candidate);
      best_distance = distance;
    }
  }
  return best;
}

}  // namespace

std::size_t folded_edit_distance(std::string_view a, std::string_view b) {
  return edit_distance(fold(a), fold(b));
}

std::optional<std::string> closest_match(std::string_view name,
                                         std::span<const std::string_view> candidates) {
  return closest(name, candidates);
}

std::optional<std::string> closest_match(std::string_view name,
                                         std::span<const std::string> candidates) {
  return closest(name, candidates);
}

}  // namespace clinch
