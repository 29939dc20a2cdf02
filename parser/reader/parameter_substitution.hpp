// Parameter references in keyword parameter values and data fields: a field that is exactly
// `<name>` takes the parameter's value (input-syntax.md §3.3, §6.4). A failed substitution empties
// the field and is remembered until clear_failure(), so that the caller can drop the whole line.
#pragma once

#include <string_view>

#include "base/diagnostic.hpp"
#include "parser/lexer.hpp"
#include "parser/parameters.hpp"

namespace clinch {

class ParameterSubstitution {
 public:
  ParameterSubstitution(ParameterTable& parameters, DiagnosticSink& sink)
      : parameters_(parameters), sink_(sink) {}

  void substitute(Field& field);
  // Marks every `<name>` in the text of a line that is not read as used, without reporting.
  void mark_references_used(std::string_view text);

  void clear_failure() { failed_ = false; }
  // Whether a substitution failed since the last clear_failure().
  bool failed() const { return failed_; }

 private:
  ParameterTable& parameters_;
  DiagnosticSink& sink_;
  bool failed_ = false;
};

}  // namespace clinch
