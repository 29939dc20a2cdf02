#include "base/procedure_needs.hpp"

#include <algorithm>

namespace clinch {

void ProcedureNeeds::merge(const ProcedureNeeds& other) {
  if (other.line_search_iterations > line_search_iterations) {
    line_search_iterations = other.line_search_iterations;
    line_search_reason = other.line_search_reason;
  }
  for (const std::string& note : other.notes) {
    if (std::find(notes.begin(), notes.end(), note) == notes.end()) notes.push_back(note);
  }
}

}  // namespace clinch
