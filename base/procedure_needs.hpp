// What a law asks of the procedure that runs it, besides its force, tangent and time-step wishes
// (src/behavior/behavior.hpp). The analysis plan merges the needs of every law of the model into
// one value, which the step driver reads (through StepProblem) at the start of each step without
// knowing which law asked. In base/ because laws and the solver both speak of it.
#pragma once

#include <string>
#include <vector>

namespace clinch {

struct ProcedureNeeds {
  // The line search iterations N_ls a step gets when the deck does not set *CONTROLS,
  // PARAMETERS=LINE SEARCH itself (keywords.md §16); 0: none asked for.
  int line_search_iterations = 0;
  std::string line_search_reason;  // for the run log: "the step has friction"
  // Lines for the run log at the start of each step: how the procedure treats the law.
  std::vector<std::string> notes;

  // Adds what `other` asks for: the longer line search with its reason, and each note not yet
  // here (the laws of many sections share a note).
  void merge(const ProcedureNeeds& other);
};

}  // namespace clinch
