// Keyword name → KeywordSpec table (not an if/else chain). Each keyword family contributes its
// specs through one function declared in parser/keywords/keyword_families.hpp.
#pragma once

#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "parser/keyword_spec.hpp"

namespace clinch {

class KeywordRegistry {
 public:
  // The registry of every keyword clinch knows (supported, no effect, known but unsupported).
  static const KeywordRegistry& instance();

  void add(KeywordSpec spec);
  // Lookup by folded name (upper case, no blanks).
  const KeywordSpec* find(std::string_view folded_name) const;
  // Display names ("*CONNECTOR SECTION") of all keywords, for did-you-mean.
  const std::vector<std::string>& display_names() const { return display_names_; }
  // Every spec, in the order the families registered them (for `clinch keywords`).
  std::vector<const KeywordSpec*> specs() const;

 private:
  std::vector<std::unique_ptr<KeywordSpec>> specs_;
  std::unordered_map<std::string, const KeywordSpec*> by_name_;
  std::vector<std::string> display_names_;
};

}  // namespace clinch
