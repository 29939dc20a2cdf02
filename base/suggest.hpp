// "Did you mean" support: the closest candidate to a misspelt name (input-syntax.md §2.2: edit
// distance ≤ 2, or ≤ a third of the candidate's length, compared case- and blank-insensitively).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace clinch {

// Levenshtein distance between a and b after folding case and dropping blanks.
std::size_t folded_edit_distance(std::string_view a, std::string_view b);

// The best candidate within the limit, or nullopt. An exact folded match is returned too (callers
// use that to say "names are case-sensitive").
std::optional<std::string> closest_match(std::string_view name,
                                         std::span<const std::string_view> candidates);
std::optional<std::string> closest_match(std::string_view name,
                                         std::span<const std::string> candidates);

}  // namespace clinch
