// The data lines of an *AMPLITUDE given by a formula (keywords.md §8): PERIODIC, MODULATED and
// DECAY. amplitude.cpp reads the numbers; this turns them into the formula's constants.
#pragma once

#include <vector>

#include "parser/block_context.hpp"
#include "src/model/history_model.hpp"

namespace clinch {

// One number of the data lines, with the data line it was on (0 for the first).
struct AmplitudeNumber {
  double value = 0;
  SourceLoc loc;
  int line = 0;
};

// Fills a.formula from `numbers` and applies SCALEX/SCALEY/SHIFTX/SHIFTY to it (SCALEX > 0,
// checked at the keyword line). Reports E0803 and returns false when the layout is wrong.
bool read_amplitude_formula(BlockContext& ctx, Amplitude& a,
                            const std::vector<AmplitudeNumber>& numbers);

}  // namespace clinch
