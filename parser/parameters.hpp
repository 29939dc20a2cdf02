// The *PARAMETER pre-pass (input-syntax.md §6.4): every *PARAMETER data line of the whole deck is
// collected, then evaluated in file order like one Python script. The result is the table of
// final values that `<name>` references in fields take (§3.3, §6.4 item 4).
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "base/diagnostic.hpp"
#include "parser/expression.hpp"
#include "base/source_location.hpp"

namespace clinch {

// One raw data line of a *PARAMETER block; loc is its column 1.
struct ParameterLine {
  std::string text;
  SourceLoc loc;
};

class ParameterTable {
 public:
  // Called for every *PARAMETER data line of the whole deck, in file order (blank lines and
  // '#' comment lines may be passed too; they are skipped).
  void add_line(ParameterLine line);

  // Evaluates all definitions in file order and reports E0401–E0409, W0401, W0403, W0404. Call
  // once, after the add_line calls; later calls do nothing.
  void evaluate(DiagnosticSink& sink);

  struct Entry {
    std::string name;
    ParamValue value;
    SourceLoc loc;  // the name in the final definition
    bool ok = true;
  };

  // Final value of a parameter (after the whole pre-pass), for `<name>` substitution. Marks the
  // parameter used. Returns nullptr if it is undefined (the caller reports E0402, for example
  // with report_undefined). A parameter whose definition failed returns an Entry with ok=false:
  // its error is already reported, so callers stay silent.
  const Entry* use(std::string_view name);

  // The parameter name a misspelt `name` most likely meant: a case-only mismatch first, then the
  // closest name by closest_match (suggest.hpp: edit distance ≤ 2, or ≤ a third of the length).
  std::optional<std::string> suggest(std::string_view name) const;

  // E0402 "undefined parameter 'or_N'" at loc, with the did-you-mean note of §6.4 item 4
  // ("(parameter names are case-sensitive)" for a case-only mismatch).
  void report_undefined(DiagnosticSink& sink, std::string_view name, SourceLoc loc) const;

  // W0402 for each parameter used neither by a `<name>` reference nor by another definition
  // (§6.4 item 6). Parameters whose definition failed are not reported again.
  void report_unused(DiagnosticSink& sink) const;

  // True when no line added so far holds anything but blanks and comments.
  bool empty() const { return !has_content_; }

 private:
  struct Definition {
    std::string name;
    SourceLoc name_loc;
    std::size_t line = 0;        // index into lines_
    std::size_t expr_begin = 0;  // the expression: lines_[line].text[expr_begin, expr_end)
    std::size_t expr_end = 0;
    bool statement_ok = true;  // false: the line was already rejected (E0401/E0407)
  };
  struct Slot {
    Entry entry;          // the value bound now (during evaluate) or finally (after)
    SourceLoc first_loc;  // the first definition (where W0402 points)
    bool used = false;
    bool any_failed = false;
  };

  std::optional<Definition> parse_definition(std::size_t line_index, DiagnosticSink& sink) const;
  const ParamValue* lookup_during(std::size_t def_index, std::string_view name, SourceLoc use_loc,
                                  DiagnosticSink& sink);

  std::vector<ParameterLine> lines_;
  std::vector<Definition> definitions_;
  std::map<std::string, std::vector<std::size_t>, std::less<>> definitions_by_name_;
  std::vector<std::string> names_in_order_;  // each name once, in order of first definition
  std::map<std::string, Slot, std::less<>> slots_;
  // Names referenced by a definition before their own definition (E0403 reported): they count
  // as used, so that W0402 does not add a misleading "never used".
  std::set<std::string, std::less<>> referenced_early_;
  bool has_content_ = false;
  bool evaluated_ = false;
};

}  // namespace clinch
