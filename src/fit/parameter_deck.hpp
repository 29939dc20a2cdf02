// The deck copies of a fit (`clinch fit`, docs/fit.md): the deck with the final definitions of the
// varied *PARAMETER names (input-syntax.md §6.4) replaced by `name = value`, and its relative
// *INCLUDE and INPUT= paths made absolute, so that the copy runs from another directory and the
// user's deck is never edited. Parameters defined from the varied one (`r = 2*k`) follow it,
// because the pre-pass evaluates the definitions in file order.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "src/study/deck_lines.hpp"

namespace clinch {

class ParameterDeck {
 public:
  // Reads the *PARAMETER definitions of the deck at `path` (a deck that `clinch check` passes)
  // and finds the final definition of each of `names`. Returns nullopt and sets `error` when a
  // name is not defined (with the likely meant name), is a string, or is defined in an included
  // file ("FILE:LINE:COL: error: ..." there), or when the deck cannot be read.
  static std::optional<ParameterDeck> prepare(const std::string& path,
                                              const std::vector<std::string>& names,
                                              std::string* error);

  // The deck's own values of the names, in the order given to prepare.
  const std::vector<double>& values() const { return values_; }
  // "FILE:LINE:COL" of each name's final definition, for messages.
  const std::vector<std::string>& positions() const { return positions_; }

  // The deck text with the names defined as `values`.
  std::string text(const std::vector<double>& values) const;

 private:
  std::vector<std::string> names_;
  std::vector<double> values_;
  std::vector<std::string> positions_;
  std::vector<std::string> lines_;
  std::vector<DeckLineEdit> definitions_;  // the replacement is filled in by text()
  std::vector<DeckLineEdit> includes_;
};

}  // namespace clinch
