// The decks of an increment-size study (`clinch study`): a copy of the user's deck in which every
// step's *STATIC increments are multiplied by one scale factor, written elsewhere so that the
// user's deck is never edited. DIRECT steps scale Δt₀; automatic steps scale Δt₀ and Δt_max
// (the size the driver may grow to), with Δt_min kept unless it would exceed the new Δt₀
// (keywords.md §15). INC grows with 1/scale so that a finer setting is never stopped by the
// increment limit the user set for the coarse one.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "parser/source_manager.hpp"
#include "src/model/model.hpp"
#include "src/study/deck_lines.hpp"

namespace clinch {

// The increments one step runs with at some scale.
struct ScaledIncrements {
  bool direct = false;
  double initial = 0.0, period = 0.0, minimum = 0.0, maximum = 0.0;
  int max_increments = 0;  // INC
};

// The *STATIC data and INC of one step as the deck gives them, scaled by `scale`.
ScaledIncrements scale_increments(const StaticProcedure& procedure, int max_increments,
                                  double scale);

// A deck that can be rewritten at any scale: the text of the deck file and the edits that give
// each step its scaled *STATIC data line and INC, and that make the deck's relative *INCLUDE and
// INPUT= paths absolute so that the copy reads the same files from another directory.
class ScaledDeck {
 public:
  // Prepares the edits for a deck that read without errors. Returns nullopt and sets `error`
  // ("FILE:LINE:COL: error: ...") when a *STEP or *STATIC line lies in an included file, which
  // this copy of the deck cannot change.
  static std::optional<ScaledDeck> prepare(const Model& model, const SourceManager& sources,
                                           std::string* error);

  // The deck text with every step's increments scaled by `scale`.
  std::string text(double scale) const;

 private:
  // An edit whose text depends on the scale: a step's INC or its *STATIC data line.
  struct Edit {
    std::size_t line = 0;   // 1-based
    std::size_t begin = 0;  // 1-based column of the first replaced character
    std::size_t end = 0;    // 1-based column past the last one (begin == end: insertion)
    enum class Kind { StaticData, StepInc } kind = Kind::StaticData;
    std::size_t step = 0;
  };

  std::vector<std::string> lines_;  // the deck's lines without their line ends
  struct StepIncrements {
    StaticProcedure procedure;
    int max_increments = 0;
  };
  std::vector<StepIncrements> steps_;
  std::vector<Edit> edits_;
  std::vector<DeckLineEdit> includes_;  // the include paths made absolute
};

}  // namespace clinch
